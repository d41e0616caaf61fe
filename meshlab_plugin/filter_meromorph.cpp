#include "filter_meromorph.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <vector>

#include "live_mesh.h"
#include "meromorph.h"
#include "remedy_words.h"
#include "transfer_filter.h"

FilterMeromorphPlugin::FilterMeromorphPlugin() {
  typeList << FP_CONFORMAL_SPHERICAL_PARAMETERIZATION << FP_REMESH_THROUGH_CONFORMAL_SPHERE
           << FP_TRANSFER_THROUGH_CONFORMAL_SPHERE;
  for (FilterIDType type : types())
    actionList << new QAction(filterName(type), this);
}

QString FilterMeromorphPlugin::pluginName() const {
  return "FilterMeromorph";
}

QString FilterMeromorphPlugin::filterName(FilterIDType filter) const {
  if (filter == FP_REMESH_THROUGH_CONFORMAL_SPHERE) return "Remesh through the Conformal Sphere";
  if (filter == FP_TRANSFER_THROUGH_CONFORMAL_SPHERE)
    return "Transfer Attributes through the Conformal Sphere";
  return "Conformal Spherical Parameterization";
}

QString FilterMeromorphPlugin::filterInfo(FilterIDType filter) const {
  if (filter == FP_TRANSFER_THROUGH_CONFORMAL_SPHERE)
    return "Copies vertex colors, texture coordinates (per vertex and per wedge, with the texture "
           "files) and vertex quality from one closed mesh to another of the same genus (0, 1 "
           "or 2), each vertex and face corner reading its corresponding point, found through the "
           "two surfaces' conformal maps (meromorph): the meshes need not be aligned, of the same "
           "size, pose or triangulation. A symmetric surface may be matched turned (the log "
           "warns).";
  if (filter == FP_REMESH_THROUGH_CONFORMAL_SPHERE)
    return "A new triangulation of a closed surface of any genus, sampled through its conformal "
           "map onto the (layered) sphere (meromorph): a geodesic sphere with the branch values "
           "on vertices is lifted through every layer, evened out and smoothed on the surface. "
           "The result goes into a new layer, about the given number of vertices, with the same "
           "genus; each vertex's layer of the map is its quality and the branch vertices are "
           "selected. The log gives the Hausdorff distance to the input and the angles.";
  return "Maps a surface of any genus conformally onto the sphere (meromorph: Zeng, Li, Yau, Gu "
         "2007). Genus 0 gives a one-to-one map; a torus is wrapped twice over the sphere by the "
         "Weierstrass P-function, with 4 branch points; a surface of genus g by a ratio of two "
         "holomorphic 1-forms, in 2g - 2 layers. Writes per-vertex texture coordinates, the layer "
         "of each vertex as its quality, and selects the branch vertices. A mesh in several parts "
         "has each part mapped on its own; holes are closed and non-manifold spots taken apart "
         "for the computation only (the parameters below), so the mesh keeps its faces.";
}

MeshFilterInterface::FilterClass FilterMeromorphPlugin::getClass(QAction *action) {
  if (ID(action) == FP_TRANSFER_THROUGH_CONFORMAL_SPHERE)
    return FilterClass(MeshFilterInterface::Sampling | MeshFilterInterface::Texture);
  if (ID(action) == FP_REMESH_THROUGH_CONFORMAL_SPHERE) return MeshFilterInterface::Remeshing;
  return FilterClass(MeshFilterInterface::Texture | MeshFilterInterface::Selection);
}

int FilterMeromorphPlugin::getPreConditions(QAction *) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterMeromorphPlugin::getRequirements(QAction *action) {
  if (ID(action) != FP_CONFORMAL_SPHERICAL_PARAMETERIZATION) return MeshModel::MM_NONE;
  return MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTQUALITY;
}

int FilterMeromorphPlugin::postCondition(QAction *action) const {
  if (ID(action) == FP_REMESH_THROUGH_CONFORMAL_SPHERE) return MeshModel::MM_NONE;
  if (ID(action) == FP_TRANSFER_THROUGH_CONFORMAL_SPHERE)
    return MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD |
           MeshModel::MM_VERTQUALITY;
  // With vertices added where the map needs them, the faces change too.
  return MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTQUALITY |
         MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNUMBER |
         MeshModel::MM_FACENUMBER | MeshModel::MM_FACEVERT;
}

void FilterMeromorphPlugin::initParameterSet(QAction *action, MeshDocument &document,
                                             RichParameterList &parameters) {
  if (ID(action) != FP_TRANSFER_THROUGH_CONFORMAL_SPHERE) {
    if (document.mm()) initParameterSet(action, *document.mm(), parameters);
    return;
  }
  // As MeshLab's Vertex Attribute Transfer: from the current layer to another one.
  MeshModel *other = document.mm();
  for (MeshModel *model : document.meshList)
    if (model != document.mm()) other = model;
  parameters.addParam(RichMesh("sourceMesh", document.mm(), &document, "Copy from",
                               "The mesh whose colors, texture coordinates and quality are read"));
  parameters.addParam(RichMesh("targetMesh", other, &document, "Copy to",
                               "The mesh whose vertices and face corners receive them"));
  parameters.addParam(RichBool("colors", true, "Vertex colors", "Copy the vertex colors"));
  parameters.addParam(RichBool("texCoords", true, "Texture coordinates",
                               "Copy the texture coordinates, per vertex and per wedge (each face "
                               "from one side of a seam), and the texture file names"));
  parameters.addParam(RichBool("quality", true, "Vertex quality", "Copy the vertex quality"));
}

void FilterMeromorphPlugin::initParameterSet(QAction *action, MeshModel &model,
                                             RichParameterList &parameters) {
  if (ID(action) == FP_REMESH_THROUGH_CONFORMAL_SPHERE) {
    parameters.addParam(RichInt("targetVertices", model.cm.vn, "Vertices",
                                "About how many vertices the new mesh should have (the default "
                                "is the current mesh's count)."));
    parameters.addParam(RichFloat("edgeLength", 0.0f, "Edge length",
                                  "About this edge length, in the mesh's units, instead of the "
                                  "vertex count (0: use Vertices)."));
    parameters.addParam(RichFloat("maxError", 0.0f, "Max. surface distance (%)",
                                  "The new mesh within this distance of the current one both "
                                  "ways (Hausdorff, in percent of the bounding box diagonal), "
                                  "with as few vertices as the tries find, instead of the vertex "
                                  "count (0: use Vertices)."));
    parameters.addParam(RichBool(
        "areaCorrect", true, "Even out the sampling",
        "First move the map by the Moebius transformation that spreads the surface's area most "
        "evenly over the sphere, so that the samples fall more evenly on the surface."));
    return;
  }
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
  parameters.addParam(RichBool(
      "strict", false, "Strict",
      "Refuse the mesh, naming the problem, instead of dealing with it for the computation: "
      "holes and non-manifold spots (whatever the two options above say), duplicate vertices "
      "along seams (welded), duplicate faces, faces that use a vertex twice and unreferenced "
      "vertices (left out; the mesh keeps them all)."));
  parameters.addParam(RichBool("packUv", false, "Pack the parts' texture coordinates",
                               "Several parts, spherical coordinates: each part's texture in its "
                               "own cell of the unit square instead of each filling it."));
  parameters.addParam(RichBool(
      "addVertices", true, "Add vertices where needed",
      "Where the mesh's triangles cannot carry the map without turning some over (slivers, "
      "coarse faces at branch points), add the vertices it needs after the mesh's own and cut the "
      "faces they lie on. Off: keep the mesh as it is and report the map as not valid."));
}

bool FilterMeromorphPlugin::fail(const QString &filter, const QString &message) {
  errorMessage = message;
  Log(GLLogStream::WARNING, "%s failed: %s", filter.toStdString().c_str(),
      message.toStdString().c_str());
  return false;
}

namespace {

meromorph_options filter_options(const RichParameterList &parameters, ProgressBridge &bridge) {
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
  options.strict = parameters.getBool("strict") ? 1 : 0;
  options.add_vertices = parameters.getBool("addVertices") ? 1 : 0;
  options.progress = report_progress;
  options.progress_user = &bridge;
  return options;
}

// Everything the filter uses from a result, read through the C ABI.
struct FetchedMap {
  std::vector<double> uv, corners, layered, added;
  std::vector<int32_t> surface_triangles, surface_source;
  std::vector<int32_t> layers, sphere_triangles, sphere_layers, branch_vertices, branch_degrees;
  meromorph_distortion distortion;
  int genus = 0, degree = 0;
  bool riemann_hurwitz = false, valid = false;
  std::string invalid_reasons, advice;
  QJsonArray notes; // what was closed or split for the computation, in the report's words
};

FetchedMap fetch_map(const meromorph_result *result) {
  FetchedMap map;
  // The surface as written: the mesh's vertices, then any the map needed added.
  const size_t vertex_count = meromorph_vertex_count(result),
               face_count = meromorph_triangle_count(result);
  map.added.resize(3 * meromorph_added_vertex_count(result));
  meromorph_added_vertices(result, nullptr, nullptr, map.added.data());
  map.surface_triangles.resize(3 * face_count);
  map.surface_source.resize(face_count);
  meromorph_surface_triangles(result, map.surface_triangles.data(), map.surface_source.data());
  map.uv.resize(2 * vertex_count);
  map.corners.resize(6 * face_count);
  map.layers.resize(vertex_count);
  meromorph_vertex_uvs(result, map.uv.data());
  meromorph_corner_uvs(result, map.corners.data());
  meromorph_layers(result, map.layers.data());
  // The layered sphere as a mesh (with copies of vertices split at non-manifold spots).
  const size_t sphere_vertex_count = meromorph_sphere_vertex_count(result);
  map.layered.resize(3 * sphere_vertex_count);
  map.sphere_triangles.resize(3 * face_count);
  map.sphere_layers.resize(sphere_vertex_count);
  meromorph_sphere_mesh(result, map.layered.data(), map.sphere_triangles.data(), nullptr,
                        map.sphere_layers.data(), nullptr, nullptr);
  map.branch_vertices.resize(meromorph_branch_point_count(result));
  map.branch_degrees.resize(map.branch_vertices.size());
  if (!map.branch_vertices.empty())
    meromorph_branch_points(result, map.branch_vertices.data(), map.branch_degrees.data());
  meromorph_map_distortion_away_from_branch_points(result, &map.distortion);
  map.genus = meromorph_genus(result);
  map.degree = meromorph_degree(result);
  map.riemann_hurwitz = meromorph_riemann_hurwitz_ok(result) != 0;
  map.valid = meromorph_map_valid(result) != 0;
  map.invalid_reasons = meromorph_invalid_reasons(result);
  std::vector<QString> causes;
  std::vector<int> remedies;
  for (int i = 0; i < meromorph_advice_count(result); ++i) {
    causes.push_back(QString::fromUtf8(meromorph_advice_cause(result, i)));
    remedies.push_back(meromorph_advice_remedy(result, i));
  }
  map.advice = meshlab_advice_words(causes, remedies).toStdString();
  map.notes = QJsonDocument::fromJson(QByteArray(meromorph_report_json(result)))["notes"].toArray();
  return map;
}

// The vertices the map needed added to the mesh (after its own), and the faces they cut replaced
// by the written surface's: a cut face keeps its place with one piece, the other pieces are new
// faces after the mesh's, each a copy of its face's attributes.
void add_written_vertices(MeshModel &model, const LiveMesh &before, const FetchedMap &map) {
  CMeshO &mesh = model.cm;
  // Storage indices of the live vertices and faces, the new ones after them.
  std::vector<size_t> vertex_at(before.live_of_dense.begin(), before.live_of_dense.end());
  std::vector<size_t> face_at;
  for (CFaceO *face : before.faces)
    face_at.push_back(size_t(vcg::tri::Index(mesh, face)));
  const size_t added = map.added.size() / 3, faces = map.surface_source.size();
  auto vertex = vcg::tri::Allocator<CMeshO>::AddVertices(mesh, added);
  for (size_t k = 0; k < added; ++k, ++vertex) {
    vertex->P() = Point3m(map.added[3 * k], map.added[3 * k + 1], map.added[3 * k + 2]);
    vertex_at.push_back(size_t(vcg::tri::Index(mesh, &*vertex)));
  }
  auto face = vcg::tri::Allocator<CMeshO>::AddFaces(mesh, faces - face_at.size());
  for (size_t f = face_at.size(); f < faces; ++f, ++face)
    face_at.push_back(size_t(vcg::tri::Index(mesh, &*face)));
  for (size_t f = 0; f < faces; ++f) {
    CFaceO &piece = mesh.face[face_at[f]];
    if (f >= before.faces.size())
      piece.ImportData(mesh.face[face_at[size_t(map.surface_source[f])]]);
    for (int k = 0; k < 3; ++k)
      piece.V(k) = &mesh.vert[vertex_at[size_t(map.surface_triangles[3 * f + k])]];
  }
  if (model.hasDataMask(MeshModel::MM_FACEFACETOPO))
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(mesh);
  if (model.hasDataMask(MeshModel::MM_VERTFACETOPO))
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(mesh);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(mesh);
  vcg::tri::UpdateBounding<CMeshO>::Box(mesh);
}

// Texture coordinates per vertex (and per wedge), the layer as quality, branch vertices selected.
void write_texture(CMeshO &mesh, const LiveMesh &live, const FetchedMap &map, bool wedges) {
  vcg::tri::UpdateSelection<CMeshO>::VertexClear(mesh);
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    const int d = live.dense[v];
    if (d < 0) continue;
    mesh.vert[v].T().U() = float(map.uv[2 * d]);
    mesh.vert[v].T().V() = float(map.uv[2 * d + 1]);
    mesh.vert[v].T().N() = 0;
    mesh.vert[v].Q() = float(map.layers[d]);
  }
  for (int32_t b : map.branch_vertices)
    mesh.vert[live.live_of_dense[b]].SetS();
  if (wedges)
    for (size_t f = 0; f < live.faces.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        live.faces[f]->WT(k).U() = float(map.corners[6 * f + 2 * k]);
        live.faces[f]->WT(k).V() = float(map.corners[6 * f + 2 * k + 1]);
        live.faces[f]->WT(k).N() = 0;
      }
}

// A new layer: the same faces on the layered sphere, each vertex's layer as its quality.
void add_sphere_layer(MeshDocument &document, const QString &label, const FetchedMap &map) {
  MeshModel *sphere = document.addNewMesh("", label + " layered sphere", false);
  CMeshO &on_sphere = sphere->cm;
  const size_t vertex_count = map.sphere_layers.size(),
               face_count = map.sphere_triangles.size() / 3;
  auto vertex = vcg::tri::Allocator<CMeshO>::AddVertices(on_sphere, vertex_count);
  auto face = vcg::tri::Allocator<CMeshO>::AddFaces(on_sphere, face_count);
  sphere->updateDataMask(MeshModel::MM_VERTQUALITY);
  for (size_t v = 0; v < vertex_count; ++v, ++vertex) {
    vertex->P() = Point3m(map.layered[3 * v], map.layered[3 * v + 1], map.layered[3 * v + 2]);
    vertex->Q() = float(map.sphere_layers[v]);
  }
  for (size_t f = 0; f < face_count; ++f, ++face)
    for (int k = 0; k < 3; ++k)
      face->V(k) = &on_sphere.vert[size_t(map.sphere_triangles[3 * f + k])];
  vcg::tri::UpdateBounding<CMeshO>::Box(sphere->cm);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(sphere->cm);
}

QString branch_list(const FetchedMap &map) {
  QString list;
  for (size_t i = 0; i < map.branch_vertices.size(); ++i)
    list += QString("%1%2 (e=%3)")
                .arg(i ? ", " : "")
                .arg(map.branch_vertices[i])
                .arg(map.branch_degrees[i]);
  return list;
}

} // namespace

bool FilterMeromorphPlugin::applyFilter(QAction *action, MeshDocument &document,
                                        const RichParameterList &parameters,
                                        vcg::CallBackPos *callback) {
  if (ID(action) == FP_REMESH_THROUGH_CONFORMAL_SPHERE)
    return remesh(document, parameters, callback);
  if (ID(action) == FP_TRANSFER_THROUGH_CONFORMAL_SPHERE) {
    const QString name = filterName(FP_TRANSFER_THROUGH_CONFORMAL_SPHERE);
    const TransferOutcome outcome = transfer_through_sphere(parameters, callback);
    if (!outcome.ok) return fail(name, outcome.error);
    Log("%s: %s", name.toStdString().c_str(), outcome.summary.toStdString().c_str());
    if (!outcome.warning.isEmpty())
      Log(GLLogStream::WARNING, "%s: %s", name.toStdString().c_str(),
          outcome.warning.toStdString().c_str());
    return true;
  }
  MeshModel *model = document.mm();
  if (!model)
    return fail(filterName(FP_CONFORMAL_SPHERICAL_PARAMETERIZATION), "there is no current mesh");
  CMeshO &mesh = model->cm;
  QElapsedTimer timer;
  timer.start();
  const LiveMesh live = live_mesh(mesh);
  if (live.faces.size() < 4)
    return fail(filterName(FP_CONFORMAL_SPHERICAL_PARAMETERIZATION),
                "the mesh has fewer than 4 faces: no closed surface");
  ProgressBridge bridge{callback};
  const meromorph_options options = filter_options(parameters, bridge);

  meromorph_result *result = nullptr;
  const meromorph_status status =
      meromorph_parameterize_f(live.positions.data(), live.vertex_count(), live.triangles.data(),
                               live.faces.size(), &options, &result);
  if (status != MEROMORPH_OK) {
    std::vector<int32_t> codes(size_t(meromorph_last_error_remedies(nullptr, 0)));
    meromorph_last_error_remedies(codes.data(), int(codes.size()));
    return fail(filterName(FP_CONFORMAL_SPHERICAL_PARAMETERIZATION),
                with_meshlab_remedies(
                    QString("%1 (vertex and face numbers count the mesh's live elements from 0)")
                        .arg(meromorph_last_error()),
                    std::vector<int>(codes.begin(), codes.end())));
  }
  const FetchedMap map = fetch_map(result);
  meromorph_result_free(result);

  model->updateDataMask(MeshModel::MM_VERTTEXCOORD | MeshModel::MM_VERTQUALITY);
  const bool wedges = parameters.getBool("wedgeTexCoords");
  if (wedges) model->updateDataMask(MeshModel::MM_WEDGTEXCOORD);
  if (!map.added.empty()) add_written_vertices(*model, live, map);
  write_texture(mesh, map.added.empty() ? live : live_mesh(mesh), map, wedges);
  if (parameters.getBool("layeredSphere")) add_sphere_layer(document, model->label(), map);

  Log("Conformal spherical parameterization: genus %d, degree %d, %d branch points%s%s; "
      "Riemann-Hurwitz %s; away from branch points: angle error %.2f deg, quasi-conformal mean "
      "%.3f (95th percentile %.3f), folded faces %d; %lld ms",
      map.genus, map.degree, int(map.branch_vertices.size()),
      map.branch_vertices.empty() ? "" : ": ", branch_list(map).toStdString().c_str(),
      map.riemann_hurwitz ? "holds" : "FAILS", map.distortion.angle_error_mean_degrees,
      map.distortion.quasi_conformal_mean, map.distortion.quasi_conformal_p95,
      int(map.distortion.folded_faces_away_from_branch_points), (long long)timer.elapsed());
  if (!map.added.empty())
    Log("Conformal spherical parameterization: %d vertices added where the mesh's faces could not "
        "carry the map without turning some over (after the mesh's own; the faces they lie on are "
        "cut)",
        int(map.added.size() / 3));
  for (const QJsonValue &note : map.notes)
    Log("Conformal spherical parameterization: %s", note.toString().toStdString().c_str());
  if (!map.valid)
    Log(GLLogStream::WARNING,
        "The map is not a valid branched cover of the sphere on this triangulation: %s. What to "
        "do: %s",
        map.invalid_reasons.c_str(), map.advice.c_str());
  return true;
}

bool FilterMeromorphPlugin::remesh(MeshDocument &document, const RichParameterList &parameters,
                                   vcg::CallBackPos *callback) {
  const QString name = filterName(FP_REMESH_THROUGH_CONFORMAL_SPHERE);
  MeshModel *model = document.mm();
  if (!model) return fail(name, "there is no current mesh");
  const LiveMesh live = live_mesh(model->cm);
  if (live.faces.size() < 4)
    return fail(name, "the mesh has fewer than 4 faces: no closed surface");
  ProgressBridge bridge{callback};
  meromorph_options options;
  meromorph_default_options(&options);
  options.close_holes = 1;
  options.split_nonmanifold = 1;
  options.progress = report_progress;
  options.progress_user = &bridge;
  // An edge length or a largest distance, when given, sets the size instead of the vertex count.
  options.remesh_edge_length = std::max(0.0, double(parameters.getFloat("edgeLength")));
  options.remesh_max_error = std::max(0.0, double(parameters.getFloat("maxError"))) / 100;
  const int target = options.remesh_edge_length > 0 || options.remesh_max_error > 0
                         ? 0
                         : parameters.getInt("targetVertices");
  const std::vector<double> positions(live.positions.begin(), live.positions.end());
  meromorph_remesh_result *result = nullptr;
  const meromorph_status status = meromorph_remesh_d(
      positions.data(), live.vertex_count(), live.triangles.data(), live.faces.size(), &options,
      target, parameters.getBool("areaCorrect") ? 1 : 0, &result);
  if (status != MEROMORPH_OK) {
    std::vector<int32_t> codes(size_t(meromorph_last_error_remedies(nullptr, 0)));
    meromorph_last_error_remedies(codes.data(), int(codes.size()));
    return fail(name, with_meshlab_remedies(
                          QString("%1 (vertex and face numbers count the mesh's live elements "
                                  "from 0)")
                              .arg(meromorph_last_error()),
                          std::vector<int>(codes.begin(), codes.end())));
  }
  const size_t vertex_count = meromorph_remesh_vertex_count(result),
               face_count = meromorph_remesh_triangle_count(result);
  std::vector<double> xyz(3 * vertex_count);
  std::vector<int32_t> triangles(3 * face_count), layer(vertex_count), branch(vertex_count);
  meromorph_remesh_mesh(result, xyz.data(), triangles.data(), layer.data(), branch.data(), nullptr);
  const QString summary = QString::fromUtf8(meromorph_remesh_summary(result));
  meromorph_remesh_free(result);

  MeshModel *remeshed = document.addNewMesh("", model->label() + " remeshed", true);
  CMeshO &mesh = remeshed->cm;
  remeshed->updateDataMask(MeshModel::MM_VERTQUALITY);
  auto vertex = vcg::tri::Allocator<CMeshO>::AddVertices(mesh, vertex_count);
  auto face = vcg::tri::Allocator<CMeshO>::AddFaces(mesh, face_count);
  for (size_t v = 0; v < vertex_count; ++v, ++vertex) {
    vertex->P() = Point3m(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    vertex->Q() = float(layer[v]);
    if (branch[v] >= 2) vertex->SetS();
  }
  for (size_t f = 0; f < face_count; ++f, ++face)
    for (int k = 0; k < 3; ++k)
      face->V(k) = &mesh.vert[size_t(triangles[3 * f + k])];
  vcg::tri::UpdateBounding<CMeshO>::Box(mesh);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(mesh);
  Log("Remesh through the conformal sphere: %s", summary.toStdString().c_str());
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterMeromorphPlugin)
