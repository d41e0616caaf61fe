#include "filter_meromorph.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <vector>

#include "meromorph.h"
#include "remedy_words.h"

FilterMeromorphPlugin::FilterMeromorphPlugin() {
  typeList << FP_CONFORMAL_SPHERICAL_PARAMETERIZATION;
  for (FilterIDType type : types())
    actionList << new QAction(filterName(type), this);
}

QString FilterMeromorphPlugin::pluginName() const {
  return "FilterMeromorph";
}

QString FilterMeromorphPlugin::filterName(FilterIDType) const {
  return "Conformal Spherical Parameterization";
}

QString FilterMeromorphPlugin::filterInfo(FilterIDType) const {
  return "Maps a closed surface of any genus conformally onto the sphere (meromorph: Zeng, Li, "
         "Yau, "
         "Gu 2007). Genus 0 gives a one-to-one map; a torus is wrapped twice over the sphere by "
         "the "
         "Weierstrass P-function, with 4 branch points; a surface of genus g by a ratio of two "
         "holomorphic 1-forms, in 2g - 2 layers. Writes per-vertex texture coordinates, the layer "
         "of each vertex as its quality, and selects the branch vertices. The mesh must be closed, "
         "connected, oriented and manifold (see Filters > Cleaning and Repairing).";
}

MeshFilterInterface::FilterClass FilterMeromorphPlugin::getClass(QAction *) {
  return FilterClass(MeshFilterInterface::Texture | MeshFilterInterface::Selection);
}

int FilterMeromorphPlugin::getPreConditions(QAction *) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterMeromorphPlugin::getRequirements(QAction *) {
  return MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTQUALITY;
}

int FilterMeromorphPlugin::postCondition(QAction *) const {
  return MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTQUALITY |
         MeshModel::MM_VERTFLAGSELECT;
}

void FilterMeromorphPlugin::initParameterSet(QAction *, MeshModel &,
                                             RichParameterList &parameters) {
  parameters.addParam(RichEnum(
      "uvKind", 0,
      QStringList() << "Spherical (longitude, latitude)"
                    << "Stereographic",
      "Texture coordinates",
      "Spherical: u = longitude / 2pi + 1/2, v = latitude from the north pole / pi, as in the "
      "paper's figures. Stereographic: the plane coordinate of the sphere seen from its north pole "
      "(unbounded near the pole)."));
  parameters.addParam(RichBool(
      "mobius", true, "Moebius normalization",
      "Centre the map by a Moebius transformation so that the surface's area is spread evenly "
      "over the sphere (its area-weighted centroid at the centre). Off: keep the map as "
      "computed."));
  parameters.addParam(RichInt(
      "origin", -1, "Genus 1: pole vertex",
      "For a torus: the vertex where the map has its double pole (it goes to the north pole). "
      "-1 picks a vertex where the surface is wide (not on a long thin part), trying up to four "
      "until the map is valid."));
  parameters.addParam(RichInt(
      "poleFace", -1, "Genus 0: pole face",
      "For a sphere-like mesh: the face mapped around the north pole. -1 picks a well-shaped "
      "face of about median area."));
  parameters.addParam(RichInt("formI", -1, "Genus >= 2: first form",
                              "For genus 2 or more the map is (psi_i + psi_j) / (psi_i - psi_j) "
                              "for two normalized holomorphic 1-forms: this is i (0 .. g-1). "
                              "-1 with -1 (default): a generic pair mixing all forms."));
  parameters.addParam(RichInt("formJ", -1, "Genus >= 2: second form",
                              "The index j of the second normalized holomorphic 1-form (0 .. g-1, "
                              "different from i); -1 with -1: a generic pair."));
  parameters.addParam(RichBool("wedgeTexCoords", true, "Seam-correct wedge texture coordinates",
                               "Also write per-wedge (per face corner) texture coordinates, "
                               "unwrapped across the seam at longitude 180 degrees, so textures "
                               "show no smeared band there."));
  parameters.addParam(
      RichBool("layeredSphere", false, "Create the layered sphere",
               "Add a new layer: the same vertices and faces on the sphere, layer "
               "k on the sphere of radius 1 + gap * k, so the layers can be seen."));
  parameters.addParam(RichFloat("layerGap", 0.2f, "Layer gap",
                                "Radius step between layers of the layered sphere."));
  parameters.addParam(RichBool("closeHoles", true, "Close holes",
                               "Close every hole for the computation only: the mesh keeps its "
                               "faces, the holes show as gaps on the sphere. Off: a mesh with "
                               "holes is refused."));
  parameters.addParam(RichBool(
      "splitNonManifold", true, "Split non-manifold spots",
      "Take non-manifold vertices and edges apart for the computation: the mesh keeps its "
      "vertices (texture coordinates per wedge are exact), the layered sphere gets the split "
      "vertices. Off: such a mesh is refused."));
  parameters.addParam(RichBool("packUv", false, "Pack the parts' texture coordinates",
                               "Several parts, spherical coordinates: each part's texture in its "
                               "own cell of the unit square instead of each filling it."));
}

bool FilterMeromorphPlugin::fail(const QString &message) {
  errorMessage = message;
  Log(GLLogStream::WARNING, "Conformal Spherical Parameterization failed: %s",
      message.toStdString().c_str());
  return false;
}

namespace {

struct ProgressBridge {
  vcg::CallBackPos *callback;
};

int report_progress(double fraction, const char *stage, void *user) {
  ProgressBridge *bridge = static_cast<ProgressBridge *>(user);
  // MeshLab's callback returns false to stop (MeshLab 2020.09's own never does).
  return !bridge->callback || bridge->callback(int(100 * fraction), stage) ? 1 : 0;
}

} // namespace

bool FilterMeromorphPlugin::applyFilter(QAction *, MeshDocument &document,
                                        const RichParameterList &parameters,
                                        vcg::CallBackPos *callback) {
  MeshModel *model = document.mm();
  if (!model) return fail("there is no current mesh");
  CMeshO &mesh = model->cm;
  QElapsedTimer timer;
  timer.start();

  // MeshLab's mesh may hold deleted elements: number the live ones densely.
  std::vector<int> dense(mesh.vert.size(), -1);
  std::vector<float> positions;
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    if (mesh.vert[v].IsD()) continue;
    dense[v] = int(positions.size() / 3);
    for (int k = 0; k < 3; ++k)
      positions.push_back(float(mesh.vert[v].P()[k]));
  }
  std::vector<int32_t> triangles;
  std::vector<CFaceO *> faces;
  for (CFaceO &face : mesh.face) {
    if (face.IsD()) continue;
    for (int k = 0; k < 3; ++k)
      triangles.push_back(dense[vcg::tri::Index(mesh, face.V(k))]);
    faces.push_back(&face);
  }
  if (faces.size() < 4) return fail("the mesh has fewer than 4 faces: no closed surface");

  meromorph_options options;
  meromorph_default_options(&options);
  options.uv_kind = parameters.getEnum("uvKind");
  options.mobius = parameters.getBool("mobius") ? 1 : 0;
  options.origin_vertex = parameters.getInt("origin");
  options.pole_face = parameters.getInt("poleFace");
  options.form_pair[0] = parameters.getInt("formI");
  options.form_pair[1] = parameters.getInt("formJ");
  options.layer_gap = parameters.getFloat("layerGap");
  options.close_holes = parameters.getBool("closeHoles") ? 1 : 0;
  options.split_nonmanifold = parameters.getBool("splitNonManifold") ? 1 : 0;
  options.pack_uv = parameters.getBool("packUv") && options.uv_kind == 0 ? 1 : 0;
  ProgressBridge bridge{callback};
  options.progress = report_progress;
  options.progress_user = &bridge;

  meromorph_result *result = nullptr;
  const meromorph_status status = meromorph_parameterize_f(
      positions.data(), positions.size() / 3, triangles.data(), faces.size(), &options, &result);
  if (status != MEROMORPH_OK) {
    std::vector<int32_t> codes(size_t(meromorph_last_error_remedies(nullptr, 0)));
    meromorph_last_error_remedies(codes.data(), int(codes.size()));
    return fail(with_meshlab_remedies(
        QString("%1 (vertex and face numbers count the mesh's live elements from 0)")
            .arg(meromorph_last_error()),
        std::vector<int>(codes.begin(), codes.end())));
  }

  const size_t vertex_count = positions.size() / 3;
  std::vector<double> uv(2 * vertex_count), corners(6 * faces.size());
  std::vector<int32_t> layers(vertex_count);
  meromorph_vertex_uvs(result, uv.data());
  meromorph_corner_uvs(result, corners.data());
  meromorph_layers(result, layers.data());
  // The layered sphere as a mesh (with copies of vertices split at non-manifold spots).
  const size_t sphere_vertex_count = meromorph_sphere_vertex_count(result);
  std::vector<double> layered(3 * sphere_vertex_count);
  std::vector<int32_t> sphere_triangles(3 * faces.size()), sphere_layers(sphere_vertex_count);
  meromorph_sphere_mesh(result, layered.data(), sphere_triangles.data(), nullptr,
                        sphere_layers.data(), nullptr, nullptr);
  std::vector<int32_t> branch_vertices(meromorph_branch_point_count(result)),
      branch_degrees(branch_vertices.size());
  if (!branch_vertices.empty())
    meromorph_branch_points(result, branch_vertices.data(), branch_degrees.data());
  meromorph_distortion distortion;
  meromorph_get_distortion(result, &distortion);
  const int genus = meromorph_genus(result), degree = meromorph_degree(result);
  const bool riemann_hurwitz = meromorph_riemann_hurwitz_ok(result) != 0;
  const bool valid = meromorph_map_valid(result) != 0;
  const std::string invalid_reasons = meromorph_invalid_reasons(result);
  std::vector<QString> causes;
  std::vector<int> remedies;
  for (int i = 0; i < meromorph_advice_count(result); ++i) {
    causes.push_back(QString::fromUtf8(meromorph_advice_cause(result, i)));
    remedies.push_back(meromorph_advice_remedy(result, i));
  }
  const std::string advice = meshlab_advice_words(causes, remedies).toStdString();
  // What was closed or split for the computation, in the report's words.
  const QJsonArray notes =
      QJsonDocument::fromJson(QByteArray(meromorph_report_json(result)))["notes"].toArray();
  meromorph_result_free(result);

  model->updateDataMask(MeshModel::MM_VERTTEXCOORD | MeshModel::MM_VERTQUALITY);
  const bool wedges = parameters.getBool("wedgeTexCoords");
  if (wedges) model->updateDataMask(MeshModel::MM_WEDGTEXCOORD);
  vcg::tri::UpdateSelection<CMeshO>::VertexClear(mesh);
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    if (dense[v] < 0) continue;
    mesh.vert[v].T().U() = float(uv[2 * dense[v]]);
    mesh.vert[v].T().V() = float(uv[2 * dense[v] + 1]);
    mesh.vert[v].T().N() = 0;
    mesh.vert[v].Q() = float(layers[dense[v]]);
  }
  std::vector<int> live_of_dense(vertex_count);
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    if (dense[v] >= 0) live_of_dense[dense[v]] = int(v);
  for (int32_t b : branch_vertices)
    mesh.vert[live_of_dense[b]].SetS();
  if (wedges)
    for (size_t f = 0; f < faces.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        faces[f]->WT(k).U() = float(corners[6 * f + 2 * k]);
        faces[f]->WT(k).V() = float(corners[6 * f + 2 * k + 1]);
        faces[f]->WT(k).N() = 0;
      }

  if (parameters.getBool("layeredSphere")) {
    MeshModel *sphere = document.addNewMesh("", model->label() + " layered sphere", false);
    CMeshO &on_sphere = sphere->cm;
    auto vertex = vcg::tri::Allocator<CMeshO>::AddVertices(on_sphere, sphere_vertex_count);
    auto face = vcg::tri::Allocator<CMeshO>::AddFaces(on_sphere, faces.size());
    sphere->updateDataMask(MeshModel::MM_VERTQUALITY);
    for (size_t v = 0; v < sphere_vertex_count; ++v, ++vertex) {
      vertex->P() = Point3m(layered[3 * v], layered[3 * v + 1], layered[3 * v + 2]);
      vertex->Q() = float(sphere_layers[v]);
    }
    for (size_t f = 0; f < faces.size(); ++f, ++face)
      for (int k = 0; k < 3; ++k)
        face->V(k) = &on_sphere.vert[size_t(sphere_triangles[3 * f + k])];
    vcg::tri::UpdateBounding<CMeshO>::Box(sphere->cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(sphere->cm);
  }

  QString branch_list;
  for (size_t i = 0; i < branch_vertices.size(); ++i)
    branch_list +=
        QString("%1%2 (e=%3)").arg(i ? ", " : "").arg(branch_vertices[i]).arg(branch_degrees[i]);
  Log("Conformal spherical parameterization: genus %d, degree %d, %d branch points%s%s; "
      "Riemann-Hurwitz %s; angle error %.2f deg, quasi-conformal mean %.3f, folded faces %d away "
      "from branch points; %lld ms",
      genus, degree, int(branch_vertices.size()), branch_vertices.empty() ? "" : ": ",
      branch_list.toStdString().c_str(), riemann_hurwitz ? "holds" : "FAILS",
      distortion.angle_error_mean_degrees, distortion.quasi_conformal_mean,
      int(distortion.folded_faces_away_from_branch_points), (long long)timer.elapsed());
  for (const QJsonValue &note : notes)
    Log("Conformal spherical parameterization: %s", note.toString().toStdString().c_str());
  if (!valid)
    Log(GLLogStream::WARNING,
        "The map is not a valid branched cover of the sphere on this triangulation: %s. What to "
        "do: %s",
        invalid_reasons.c_str(), advice.c_str());
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterMeromorphPlugin)
