// MeshLab filters "Conformal Spherical Parameterization", "Remesh through the Conformal Sphere" and
// "Transfer Attributes through the Conformal Sphere":
// the adapter between MeshLab's mesh and meromorph's C ABI. No mathematics here.
//
// In:  the current mesh of the document (closed, connected, oriented manifold) and the filter's
//      parameters.
// Out (transfer): the mesh copied to gets the colours, texture coordinates and quality of the
//      mesh copied from, read at corresponding points (transfer_filter.h).
// Out (remesh): a new current layer with the remeshed surface, each vertex's sheet as its
//      quality and the branch vertices selected; the quality figures in MeshLab's log.
// Out (parameterization): per-vertex texture coordinates (and per-wedge ones when asked),
// per-vertex quality = layer,
//      the branch vertices selected, optionally a new layer holding the layered sphere; genus,
//      degree, branch points, distortion and time in MeshLab's log. On bad input: errorMessage
//      and a warning in the log saying what is wrong, nothing changed.
#ifndef MEROMORPH_FILTER_MEROMORPH_H
#define MEROMORPH_FILTER_MEROMORPH_H

#include <common/interfaces.h>

class FilterMeromorphPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  enum {
    FP_CONFORMAL_SPHERICAL_PARAMETERIZATION,
    FP_REMESH_THROUGH_CONFORMAL_SPHERE,
    FP_TRANSFER_THROUGH_CONFORMAL_SPHERE
  };

  FilterMeromorphPlugin();
  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction *action) override;
  FILTER_ARITY filterArity(QAction *action) const override {
    return ID(action) == FP_TRANSFER_THROUGH_CONFORMAL_SPHERE ? FIXED : SINGLE_MESH;
  }
  int getPreConditions(QAction *) const override;
  int getRequirements(QAction *) override;
  int postCondition(QAction *) const override;
  void initParameterSet(QAction *action, MeshModel &model, RichParameterList &parameters) override;
  void initParameterSet(QAction *action, MeshDocument &document,
                        RichParameterList &parameters) override;
  bool applyFilter(QAction *action, MeshDocument &document, const RichParameterList &parameters,
                   vcg::CallBackPos *callback) override;

private:
  bool fail(const QString &filter, const QString &message);
  bool remesh(MeshDocument &document, const RichParameterList &parameters,
              vcg::CallBackPos *callback);
};

#endif
