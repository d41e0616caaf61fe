// "Transfer Attributes through the Conformal Sphere" (the work of the filter; filter_meromorph.cpp
// logs what it returns): the mesh copied to gets the colours, texture coordinates and quality of
// the mesh copied from, read at corresponding points through meromorph_match_d.
//
// In:  the filter's parameters (sourceMesh: copied from; targetMesh: copied to; colors,
//      texCoords, quality) and MeshLab's progress callback.
// Out: the mesh copied to changed, and `TransferOutcome`: ok, or the error in the user's words
//      (nothing changed); a summary line for the log and a warning when a symmetric surface may
//      have been matched turned.
#ifndef MEROMORPH_TRANSFER_FILTER_H
#define MEROMORPH_TRANSFER_FILTER_H

#include <QString>
#include <common/filter_parameter/rich_parameter_list.h>
#include <wrap/callback.h>

struct TransferOutcome {
  bool ok = false;
  QString error, summary, warning;
};

TransferOutcome transfer_through_sphere(const RichParameterList &parameters,
                                        vcg::CallBackPos *callback);

#endif
