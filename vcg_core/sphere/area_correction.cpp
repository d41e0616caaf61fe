#include "sphere/area_correction.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sphere/branch_points.h"
#include "sphere/mobius_centering.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

struct FaceAreas {
  std::vector<std::array<int, 3>> corners;
  std::vector<double> surface_share; // of the total surface area
};

FaceAreas face_areas(const Mesh &mesh, size_t stride) {
  FaceAreas out;
  double total = 0;
  for (size_t f = 0; f < mesh.face.size(); f += stride) {
    const auto &face = mesh.face[f];
    const double area = vcg::DoubleArea(face) / 2;
    if (!(area > 0)) continue;
    out.corners.push_back(
        {index_of(mesh, face.cV(0)), index_of(mesh, face.cV(1)), index_of(mesh, face.cV(2))});
    out.surface_share.push_back(area);
    total += area;
  }
  for (double &share : out.surface_share)
    share /= total;
  return out;
}

// Mean |log(image share / surface share)| after translating by c (the image shares of the faces
// taken, scaled to sum to 1 over them, so a subset of faces measures the same thing).
double distortion_after(const FaceAreas &faces, const std::vector<Eigen::Vector3d> &sphere,
                        const Eigen::Vector3d &c) {
  std::vector<double> image(faces.corners.size());
  double total = 0;
  for (size_t f = 0; f < faces.corners.size(); ++f) {
    const auto &k = faces.corners[f];
    image[f] = std::max(0.0, signed_solid_angle(ball_translate(sphere[k[0]], c),
                                                ball_translate(sphere[k[1]], c),
                                                ball_translate(sphere[k[2]], c)));
    total += image[f];
  }
  double sum = 0;
  size_t counted = 0;
  for (size_t f = 0; f < image.size(); ++f)
    if (image[f] > 0) {
      sum += std::abs(std::log(image[f] / total / faces.surface_share[f]));
      ++counted;
    }
  return counted ? sum / double(counted) : 0.0;
}

int turned_over_faces(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere) {
  const std::vector<double> solid = face_solid_angles(mesh, sphere);
  return int(std::count_if(solid.begin(), solid.end(), [](double angle) { return angle < 0; }));
}

Eigen::Vector3d in_ball(const Eigen::Vector3d &y) {
  const double r = y.norm();
  return r < 1e-300 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(std::tanh(r) / r * y);
}

// Nelder-Mead on y in R^3 (standard coefficients), from y = 0 with steps of 0.3.
template <typename Cost> Eigen::Vector3d nelder_mead(const Cost &cost, int evaluations) {
  std::array<Eigen::Vector3d, 4> x;
  std::array<double, 4> value;
  for (int i = 0; i < 4; ++i) {
    x[i] = Eigen::Vector3d::Zero();
    if (i > 0) x[i][i - 1] = 0.3;
    value[i] = cost(x[i]);
  }
  for (int used = 4; used < evaluations;) {
    std::array<int, 4> order{0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return value[a] < value[b]; });
    const int best = order[0], worst = order[3], second = order[2];
    if (value[worst] - value[best] < 1e-9 * (1 + std::abs(value[best]))) break;
    const Eigen::Vector3d mid = (x[order[0]] + x[order[1]] + x[order[2]]) / 3;
    const Eigen::Vector3d reflected = mid + (mid - x[worst]);
    const double reflected_value = cost(reflected);
    ++used;
    if (reflected_value < value[best]) {
      const Eigen::Vector3d expanded = mid + 2 * (mid - x[worst]);
      const double expanded_value = cost(expanded);
      ++used;
      const bool expand = expanded_value < reflected_value;
      x[worst] = expand ? expanded : reflected;
      value[worst] = expand ? expanded_value : reflected_value;
    } else if (reflected_value < value[second]) {
      x[worst] = reflected;
      value[worst] = reflected_value;
    } else {
      const Eigen::Vector3d contracted = mid + 0.5 * (x[worst] - mid);
      const double contracted_value = cost(contracted);
      ++used;
      if (contracted_value < value[worst]) {
        x[worst] = contracted;
        value[worst] = contracted_value;
      } else {
        for (int i = 0; i < 4; ++i)
          if (i != best) {
            x[i] = x[best] + 0.5 * (x[i] - x[best]);
            value[i] = cost(x[i]);
            ++used;
          }
      }
    }
  }
  return x[std::min_element(value.begin(), value.end()) - value.begin()];
}

} // namespace

std::vector<double> sample_shares(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                  int degree) {
  double surface_total = 0;
  for (const auto &face : mesh.face)
    surface_total += vcg::DoubleArea(face) / 2;
  std::vector<double> shares(mesh.face.size(), 0.0);
  const double image_total = 4 * M_PI * std::max(degree, 1);
  const std::vector<double> solid = face_solid_angles(mesh, sphere);
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const double area = vcg::DoubleArea(mesh.face[f]) / 2;
    if (area > 0 && solid[f] > 0) shares[f] = (solid[f] / image_total) / (area / surface_total);
  }
  return shares;
}

double area_distortion(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere, int degree) {
  const std::vector<double> shares = sample_shares(mesh, sphere, degree);
  double sum = 0;
  size_t counted = 0;
  for (double share : shares)
    if (share > 0) {
      sum += std::abs(std::log(share));
      ++counted;
    }
  return counted ? sum / double(counted) : 0.0;
}

AreaCorrection correct_area(const Mesh &mesh, std::vector<Eigen::Vector3d> &sphere, int degree) {
  AreaCorrection out;
  out.distortion_before = out.distortion_after = area_distortion(mesh, sphere, degree);
  const size_t stride = std::max<size_t>(1, mesh.face.size() / 200000);
  const FaceAreas faces = face_areas(mesh, stride);
  if (faces.corners.empty()) return out;
  const Eigen::Vector3d y = nelder_mead(
      [&](const Eigen::Vector3d &y) { return distortion_after(faces, sphere, in_ball(y)); }, 200);
  // A Moebius map keeps circles, not the chords of the faces' images: a face with a corner near
  // 180 degrees (at a double point) can turn over. The translation is shortened until no more
  // faces are turned over than before.
  const int folded_before = turned_over_faces(mesh, sphere);
  std::vector<Eigen::Vector3d> moved(sphere.size());
  for (double scale = 1.0; scale > 0.01; scale *= 0.5) {
    const Eigen::Vector3d c = in_ball(scale * y);
    for (size_t v = 0; v < sphere.size(); ++v)
      moved[v] = ball_translate(sphere[v], c);
    const double after = area_distortion(mesh, moved, degree);
    if (!(after < out.distortion_before)) return out;
    if (turned_over_faces(mesh, moved) > folded_before) continue;
    sphere = std::move(moved);
    out.applied = true;
    out.distortion_after = after;
    out.translation = c;
    return out;
  }
  return out;
}

} // namespace meromorph
