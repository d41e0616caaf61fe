// "Transfer Attributes through the Conformal Sphere": the plugin's adapter for meromorph_match_d.
// Every vertex and face corner of the mesh copied to reads the mesh copied from at its
// corresponding point, found through the two surfaces' conformal spheres (genus 0), flat tori
// (genus 1) or canonical maps (genus 2), whatever their placement, size, pose or triangulation
// (MeshLab's Vertex Attribute Transfer reads the closest point in space instead). Copies what the
// mesh copied from has: vertex colours, vertex texture coordinates, wedge texture coordinates (each
// receiving face from the one face that holds its centre's image, so no face straddles a seam; with
// the texture files' names) and vertex quality. No mathematics here.
#include "transfer_filter.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <common/meshmodel.h>
#include <vector>

#include "live_mesh.h"
#include "meromorph.h"
#include "remedy_words.h"

TransferOutcome transfer_through_sphere(const RichParameterList &parameters,
                                        vcg::CallBackPos *callback) {
  TransferOutcome outcome;
  MeshModel *from = parameters.getMesh("sourceMesh"), *to = parameters.getMesh("targetMesh");
  if (!from || !to) {
    outcome.error = "choose the mesh to copy from and the mesh to copy to";
    return outcome;
  }
  if (from == to) {
    outcome.error = "the mesh to copy from and the mesh to copy to are one layer";
    return outcome;
  }
  const LiveMesh source = live_mesh(from->cm), receiver = live_mesh(to->cm);
  const std::vector<double> source_xyz(source.positions.begin(), source.positions.end());
  const std::vector<double> receiver_xyz(receiver.positions.begin(), receiver.positions.end());
  ProgressBridge bridge{callback};
  meromorph_options options;
  meromorph_default_options(&options);
  options.progress = report_progress;
  options.progress_user = &bridge;
  meromorph_match_result *result = nullptr;
  const meromorph_status status = meromorph_match_d(
      receiver_xyz.data(), receiver.vertex_count(), receiver.triangles.data(),
      receiver.faces.size(), source_xyz.data(), source.vertex_count(), source.triangles.data(),
      source.faces.size(), nullptr, 0, &options, &result);
  if (status != MEROMORPH_OK) {
    std::vector<int32_t> codes(size_t(meromorph_last_error_remedies(nullptr, 0)));
    meromorph_last_error_remedies(codes.data(), int(codes.size()));
    outcome.error =
        with_meshlab_remedies(QString("'%1' onto '%2': %3 (vertex numbers count each mesh's live "
                                      "vertices from 0; the source is '%2', the target '%1')")
                                  .arg(to->label(), from->label(), meromorph_last_error()),
                              std::vector<int>(codes.begin(), codes.end()));
    return outcome;
  }
  const size_t n = receiver.vertex_count(), t = receiver.faces.size();
  std::vector<int32_t> vertex_face(n), triangle_face(t);
  std::vector<double> vertex_weights(3 * n), triangle_weights(9 * t);
  meromorph_match_points(result, vertex_face.data(), vertex_weights.data(), nullptr);
  meromorph_match_triangles(result, triangle_face.data(), triangle_weights.data());
  const QJsonObject report =
      QJsonDocument::fromJson(QByteArray(meromorph_match_report_json(result))).object();
  meromorph_match_free(result);

  // Per receiving vertex: the weighted sum over the corners of its face in the mesh copied from.
  const auto at_vertex = [&](size_t v, auto value_of_corner) {
    const CFaceO &face = *source.faces[size_t(std::max(vertex_face[v], 0))];
    auto sum = value_of_corner(face, 0) * vertex_weights[3 * v];
    for (int j = 1; j < 3; ++j)
      sum += value_of_corner(face, j) * vertex_weights[3 * v + size_t(j)];
    return sum;
  };
  QStringList copied;
  CMeshO &mesh = to->cm;
  if (parameters.getBool("colors") && from->hasDataMask(MeshModel::MM_VERTCOLOR)) {
    to->updateDataMask(MeshModel::MM_VERTCOLOR);
    for (size_t v = 0; v < n; ++v) {
      if (vertex_face[v] < 0) continue;
      const vcg::Point4d c = at_vertex(v, [](const CFaceO &face, int j) {
        const vcg::Color4b &color = face.cV(j)->cC();
        return vcg::Point4d(color[0], color[1], color[2], color[3]);
      });
      vcg::Color4b &out = mesh.vert[size_t(receiver.live_of_dense[v])].C();
      for (int k = 0; k < 4; ++k)
        out[k] = (unsigned char)std::lround(std::min(255.0, std::max(0.0, c[k])));
    }
    copied << "vertex colors";
  }
  if (parameters.getBool("texCoords") && from->hasDataMask(MeshModel::MM_VERTTEXCOORD)) {
    to->updateDataMask(MeshModel::MM_VERTTEXCOORD);
    for (size_t v = 0; v < n; ++v) {
      if (vertex_face[v] < 0) continue;
      const vcg::Point2d uv = at_vertex(v, [](const CFaceO &face, int j) {
        return vcg::Point2d(face.cV(j)->cT().U(), face.cV(j)->cT().V());
      });
      auto &out = mesh.vert[size_t(receiver.live_of_dense[v])].T();
      out.U() = float(uv[0]), out.V() = float(uv[1]);
      out.N() = source.faces[size_t(vertex_face[v])]->cV(0)->cT().N();
    }
    copied << "vertex texture coordinates";
  }
  if (parameters.getBool("texCoords") && from->hasDataMask(MeshModel::MM_WEDGTEXCOORD)) {
    to->updateDataMask(MeshModel::MM_WEDGTEXCOORD);
    for (size_t f = 0; f < t; ++f) {
      if (triangle_face[f] < 0) continue;
      const CFaceO &face = *source.faces[size_t(triangle_face[f])];
      for (int k = 0; k < 3; ++k) {
        double u = 0, w = 0;
        for (int j = 0; j < 3; ++j) {
          const double weight = triangle_weights[9 * f + 3 * size_t(k) + size_t(j)];
          u += weight * face.cWT(j).U(), w += weight * face.cWT(j).V();
        }
        auto &out = receiver.faces[f]->WT(k);
        out.U() = float(u), out.V() = float(w), out.N() = face.cWT(0).N();
      }
    }
    if (mesh.textures.empty()) mesh.textures = from->cm.textures;
    copied << "wedge texture coordinates";
  }
  if (parameters.getBool("quality") && from->hasDataMask(MeshModel::MM_VERTQUALITY)) {
    to->updateDataMask(MeshModel::MM_VERTQUALITY);
    for (size_t v = 0; v < n; ++v)
      if (vertex_face[v] >= 0)
        mesh.vert[size_t(receiver.live_of_dense[v])].Q() =
            at_vertex(v, [](const CFaceO &face, int j) { return double(face.cV(j)->cQ()); });
    copied << "vertex quality";
  }
  const QJsonObject matched = report["matched_mesh"].toObject();
  outcome.summary =
      QString("'%1' -> '%2': %3 (genus %4, %5; the matched mesh's angle error %6 deg, %7 folded "
              "faces)")
          .arg(from->label(), to->label(),
               copied.isEmpty() ? QString("nothing to copy") : copied.join(", "))
          .arg(report["genus"].toInt())
          .arg(report["method"].toString())
          .arg(matched["angle_error_mean_degrees"].toDouble(), 0, 'f', 2)
          .arg(matched["folded_faces"].toInt());
  const int alternatives = report["alignment"].toObject()["alternatives"].toArray().size();
  if (alternatives > 0)
    outcome.warning = QString("%1 other alignments fit almost as well (a symmetric surface): the "
                              "copy may be turned; landmarks fix it in the command-line tool "
                              "(meromorph match --landmarks)")
                          .arg(alternatives);
  outcome.ok = true;
  return outcome;
}
