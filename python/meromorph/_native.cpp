// meromorph._native: the C library (libmeromorph.so, meromorph.h) for Python, through pybind11.
//
// In:  numpy arrays (positions n x 3 float64 or float32, triangles m x 3 integers), option
//      dictionaries with the C struct's field names, an optional progress callable.
// Out: numpy arrays filled by the C library's getters, the JSON reports as text; a failure is
//      raised as NativeError(status, message, remedies) for the package to word (meromorph/
//      __init__.py). The GIL is released while the library works; the progress callable is called
//      with it held, and Ctrl+C (or an exception in the callable) cancels the work.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "meromorph.h"

namespace py = pybind11;

namespace {

using Positions = py::array_t<double, py::array::c_style | py::array::forcecast>;
using FloatPositions = py::array_t<float, py::array::c_style>;
using Triangles = py::array_t<int32_t, py::array::c_style | py::array::forcecast>;

// Raised by every failed call: (status, message, remedies) for meromorph/__init__.py to word.
// Made once with the module and never freed (the module holds it too).
PyObject *native_error = nullptr;

[[noreturn]] void raise_last_error(meromorph_status status) {
  std::vector<int32_t> remedies(16);
  const int count = meromorph_last_error_remedies(remedies.data(), int(remedies.size()));
  remedies.resize(size_t(std::max(0, std::min(count, 16))));
  PyErr_SetObject(native_error,
                  py::make_tuple(int(status), std::string(meromorph_last_error()), remedies).ptr());
  throw py::error_already_set();
}

// The progress callable, called from the library with the GIL taken back; an exception in it (or
// a pending Ctrl+C) cancels the work and is raised when the call returns.
struct ProgressRelay {
  py::object callback;
  std::unique_ptr<py::error_already_set> error;

  static int relay(double fraction, const char *stage, void *user) {
    auto *self = static_cast<ProgressRelay *>(user);
    py::gil_scoped_acquire gil;
    if (self->error) return 0;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!self->callback.is_none()) {
        py::object go_on = self->callback(fraction, stage);
        if (!go_on.is_none() && !go_on.cast<bool>()) return 0;
      }
      return 1;
    } catch (py::error_already_set &error) {
      self->error = std::make_unique<py::error_already_set>(std::move(error));
      return 0;
    }
  }

  // After the call: the callable's exception first, then the library's failure.
  void check(meromorph_status status) {
    if (error) {
      error->restore();
      error.reset();
      throw py::error_already_set();
    }
    if (status != MEROMORPH_OK) raise_last_error(status);
  }
};

meromorph_options options_from(const py::dict &given, ProgressRelay &relay) {
  meromorph_options options;
  meromorph_default_options(&options);
  for (auto item : given) {
    const std::string key = item.first.cast<std::string>();
    const py::handle value = item.second;
    if (key == "uv_kind")
      options.uv_kind = value.cast<int>();
    else if (key == "mobius")
      options.mobius = value.cast<int>();
    else if (key == "origin_vertex")
      options.origin_vertex = value.cast<int>();
    else if (key == "form_pair") {
      const auto pair = value.cast<std::vector<int>>();
      if (pair.size() != 2) throw py::value_error("form_pair takes two form indices");
      options.form_pair[0] = pair[0], options.form_pair[1] = pair[1];
    } else if (key == "layer_gap")
      options.layer_gap = value.cast<double>();
    else if (key == "pole_face")
      options.pole_face = value.cast<int>();
    else if (key == "close_holes")
      options.close_holes = value.cast<int>();
    else if (key == "split_nonmanifold")
      options.split_nonmanifold = value.cast<int>();
    else if (key == "pack_uv")
      options.pack_uv = value.cast<int>();
    else if (key == "area_correct")
      options.area_correct = value.cast<int>();
    else if (key == "strict")
      options.strict = value.cast<int>();
    else if (key == "add_vertices")
      options.add_vertices = value.cast<int>();
    else if (key == "remesh_edge_length")
      options.remesh_edge_length = value.cast<double>();
    else if (key == "remesh_max_error")
      options.remesh_max_error = value.cast<double>();
    else
      throw py::value_error("unknown option " + key);
  }
  options.progress = &ProgressRelay::relay;
  options.progress_user = &relay;
  return options;
}

// The caller's arrays as the library takes them: float64 (or float32 as it is) positions n x 3,
// int32 triangles m x 3; converted (copied) only when their type or layout differs.
struct InputArrays {
  py::array positions;
  Triangles triangles;
  bool single = false;
  size_t vertices = 0, faces = 0;

  InputArrays(const py::array &V, const py::array &F) {
    if (py::isinstance<FloatPositions>(V) && (V.flags() & py::array::c_style)) {
      positions = V, single = true;
    } else {
      positions = Positions::ensure(V);
      if (!positions) throw py::error_already_set();
    }
    if (positions.ndim() != 2 || positions.shape(1) != 3)
      throw py::value_error("positions must be an array of shape (n, 3); got " +
                            std::string(py::str(V.attr("shape"))));
    const py::array indices = py::array::ensure(F);
    if (!indices || indices.ndim() != 2 || indices.shape(1) != 3)
      throw py::value_error("triangles must be an array of shape (m, 3)");
    if (!py::isinstance<py::array_t<int32_t>>(indices)) {
      // Other integer types: checked against int32's range before they are converted.
      const py::module_ numpy = py::module_::import("numpy");
      if (!numpy.attr("issubdtype")(indices.dtype(), numpy.attr("integer")).cast<bool>())
        throw py::value_error("triangles must hold integers (vertex indices)");
      if (indices.size() > 0) {
        const long long low = numpy.attr("min")(indices).cast<long long>();
        const long long high = numpy.attr("max")(indices).cast<long long>();
        if (low < INT32_MIN || high > INT32_MAX)
          throw py::value_error("a triangle index is beyond 32 bits (" + std::to_string(low) +
                                " to " + std::to_string(high) + ")");
      }
    }
    triangles = Triangles::ensure(indices);
    vertices = size_t(positions.shape(0)), faces = size_t(triangles.shape(0));
  }
  const double *doubles() const { return static_cast<const double *>(positions.data()); }
  const float *floats() const { return static_cast<const float *>(positions.data()); }
};

template <typename T> py::array_t<T> filled(std::vector<py::ssize_t> shape) {
  return py::array_t<T>(shape);
}

// A map made by meromorph_parameterize_*; the getters copy into new numpy arrays.
class Map {
public:
  explicit Map(meromorph_result *result) : result_(result, meromorph_result_free) {}
  const meromorph_result *get() const { return result_.get(); }

private:
  std::unique_ptr<meromorph_result, void (*)(meromorph_result *)> result_;
};

Map parameterize(const py::array &V, const py::array &F, const py::dict &options,
                 const py::object &progress) {
  InputArrays arrays(V, F);
  ProgressRelay relay{progress, nullptr};
  const meromorph_options settings = options_from(options, relay);
  meromorph_result *result = nullptr;
  meromorph_status status;
  {
    py::gil_scoped_release release;
    status =
        arrays.single
            ? meromorph_parameterize_f(arrays.floats(), arrays.vertices, arrays.triangles.data(),
                                       arrays.faces, &settings, &result)
            : meromorph_parameterize_d(arrays.doubles(), arrays.vertices, arrays.triangles.data(),
                                       arrays.faces, &settings, &result);
  }
  Map map(result);
  relay.check(status);
  return map;
}

py::dict map_arrays(const Map &map) {
  const meromorph_result *r = map.get();
  const auto n = py::ssize_t(meromorph_vertex_count(r)),
             m = py::ssize_t(meromorph_triangle_count(r));
  const auto b = py::ssize_t(meromorph_branch_point_count(r));
  const auto a = py::ssize_t(meromorph_added_vertex_count(r));
  const auto s = py::ssize_t(meromorph_sphere_vertex_count(r));
  auto sphere = filled<double>({n, 3}), layered = filled<double>({n, 3});
  auto uv = filled<double>({n, 2}), corner_uv = filled<double>({m, 3, 2});
  auto layer = filled<int32_t>({n}), component = filled<int32_t>({n});
  auto triangles = filled<int32_t>({m, 3}), source_triangle = filled<int32_t>({m});
  auto branch_vertices = filled<int32_t>({b}), branch_degrees = filled<int32_t>({b});
  auto added_xyz = filled<double>({a, 3});
  auto added_on = filled<int32_t>({a});
  auto added_barycentric = filled<double>({a, 2});
  auto sphere_xyz = filled<double>({s, 3});
  auto sphere_triangles = filled<int32_t>({m, 3});
  auto sphere_source = filled<int32_t>({s}), sphere_layer = filled<int32_t>({s});
  auto sphere_branch = filled<int32_t>({s});
  {
    py::gil_scoped_release release;
    meromorph_sphere_positions(r, sphere.mutable_data());
    meromorph_layered_positions(r, layered.mutable_data());
    meromorph_vertex_uvs(r, uv.mutable_data());
    meromorph_corner_uvs(r, corner_uv.mutable_data());
    meromorph_layers(r, layer.mutable_data());
    meromorph_vertex_components(r, component.mutable_data());
    meromorph_surface_triangles(r, triangles.mutable_data(), source_triangle.mutable_data());
    if (b)
      meromorph_branch_points(r, branch_vertices.mutable_data(), branch_degrees.mutable_data());
    if (a)
      meromorph_added_vertices(r, added_on.mutable_data(), added_barycentric.mutable_data(),
                               added_xyz.mutable_data());
    meromorph_sphere_mesh(r, sphere_xyz.mutable_data(), sphere_triangles.mutable_data(),
                          sphere_source.mutable_data(), sphere_layer.mutable_data(), nullptr,
                          sphere_branch.mutable_data());
  }
  py::dict out;
  out["sphere"] = sphere, out["layered"] = layered, out["uv"] = uv, out["corner_uv"] = corner_uv;
  out["layer"] = layer, out["component"] = component, out["triangles"] = triangles;
  out["source_triangle"] = source_triangle, out["branch_vertices"] = branch_vertices;
  out["branch_degrees"] = branch_degrees, out["added_xyz"] = added_xyz;
  out["added_on"] = added_on, out["added_barycentric"] = added_barycentric;
  out["sphere_mesh"] = py::make_tuple(sphere_xyz, sphere_triangles);
  out["sphere_source_vertex"] = sphere_source, out["sphere_layer"] = sphere_layer;
  out["sphere_branch"] = sphere_branch;
  out["genus"] = meromorph_genus(r), out["degree"] = meromorph_degree(r);
  out["valid"] = meromorph_map_valid(r) == 1;
  out["riemann_hurwitz_ok"] = meromorph_riemann_hurwitz_ok(r) == 1;
  out["invalid_reasons"] = std::string(meromorph_invalid_reasons(r));
  py::list advice;
  for (int k = 0; k < meromorph_advice_count(r); ++k)
    advice.append(
        py::make_tuple(std::string(meromorph_advice_cause(r, k)), meromorph_advice_remedy(r, k)));
  out["advice"] = advice;
  out["report"] = std::string(meromorph_report_json(r));
  return out;
}

void write_map(const Map &map, const py::object &surface, const py::object &sphere,
               const py::object &report, const std::vector<std::string> &protected_paths) {
  const auto text = [](const py::object &path) {
    return path.is_none() ? std::string() : py::str(path).cast<std::string>();
  };
  const std::string surface_path = text(surface), sphere_path = text(sphere),
                    report_path = text(report);
  std::vector<const char *> protect;
  for (const std::string &path : protected_paths)
    protect.push_back(path.c_str());
  meromorph_status status;
  {
    py::gil_scoped_release release;
    status = meromorph_write_map(map.get(), surface.is_none() ? nullptr : surface_path.c_str(),
                                 sphere.is_none() ? nullptr : sphere_path.c_str(),
                                 report.is_none() ? nullptr : report_path.c_str(), protect.data(),
                                 protect.size());
  }
  if (status != MEROMORPH_OK) raise_last_error(status);
}

py::tuple read_mesh(const std::string &path) {
  meromorph_mesh *mesh = nullptr;
  meromorph_status status;
  {
    py::gil_scoped_release release;
    status = meromorph_read_mesh(path.c_str(), &mesh);
  }
  if (status != MEROMORPH_OK) raise_last_error(status);
  std::unique_ptr<meromorph_mesh, void (*)(meromorph_mesh *)> owned(mesh, meromorph_mesh_free);
  auto V = filled<double>({py::ssize_t(meromorph_mesh_vertex_count(mesh)), 3});
  auto F = filled<int32_t>({py::ssize_t(meromorph_mesh_triangle_count(mesh)), 3});
  meromorph_mesh_arrays(mesh, V.mutable_data(), F.mutable_data());
  return py::make_tuple(V, F, std::string(meromorph_mesh_notes(mesh)));
}

std::string forms(const py::array &V, const py::array &F, const py::object &progress) {
  InputArrays arrays(V, F);
  const Positions positions = Positions::ensure(arrays.positions);
  ProgressRelay relay{progress, nullptr};
  const meromorph_options settings = options_from(py::dict(), relay);
  meromorph_forms_result *result = nullptr;
  meromorph_status status;
  {
    py::gil_scoped_release release;
    status = meromorph_forms_d(positions.data(), arrays.vertices, arrays.triangles.data(),
                               arrays.faces, &settings, &result);
  }
  std::unique_ptr<meromorph_forms_result, void (*)(meromorph_forms_result *)> owned(
      result, meromorph_forms_free);
  relay.check(status);
  return meromorph_forms_report_json(result);
}

py::dict match(const py::array &source_V, const py::array &source_F, const py::array &target_V,
               const py::array &target_F, const py::array_t<int32_t> &pairs,
               const py::object &progress) {
  InputArrays source(source_V, source_F), target(target_V, target_F);
  const Positions source_positions = Positions::ensure(source.positions);
  const Positions target_positions = Positions::ensure(target.positions);
  const py::array_t<int32_t, py::array::c_style | py::array::forcecast> landmarks(pairs);
  ProgressRelay relay{progress, nullptr};
  const meromorph_options settings = options_from(py::dict(), relay);
  meromorph_match_result *result = nullptr;
  meromorph_status status;
  {
    py::gil_scoped_release release;
    status = meromorph_match_d(source_positions.data(), source.vertices, source.triangles.data(),
                               source.faces, target_positions.data(), target.vertices,
                               target.triangles.data(), target.faces,
                               landmarks.size() ? landmarks.data() : nullptr,
                               size_t(landmarks.size() / 2), &settings, &result);
  }
  std::unique_ptr<meromorph_match_result, void (*)(meromorph_match_result *)> owned(
      result, meromorph_match_free);
  relay.check(status);
  const auto n = py::ssize_t(meromorph_match_vertex_count(result));
  auto face = filled<int32_t>({n});
  auto weights = filled<double>({n, 3}), points = filled<double>({n, 3});
  meromorph_match_points(result, face.mutable_data(), weights.mutable_data(),
                         points.mutable_data());
  const auto m = py::ssize_t(meromorph_match_triangle_count(result));
  auto triangle_face = filled<int32_t>({m});
  auto triangle_weights = filled<double>({m, 3, 3});
  meromorph_match_triangles(result, triangle_face.mutable_data(), triangle_weights.mutable_data());
  py::dict out;
  out["triangle_face"] = triangle_face, out["triangle_weights"] = triangle_weights;
  out["target_face"] = face, out["weights"] = weights, out["points"] = points;
  out["report"] = std::string(meromorph_match_report_json(result));
  return out;
}

py::dict remesh(const py::array &V, const py::array &F, const py::dict &options,
                long long target_vertices, bool area_correct, const py::object &progress) {
  InputArrays arrays(V, F);
  ProgressRelay relay{progress, nullptr};
  const meromorph_options settings = options_from(options, relay);
  meromorph_remesh_result *result = nullptr;
  meromorph_status status;
  {
    py::gil_scoped_release release;
    status = arrays.single ? meromorph_remesh_f(arrays.floats(), arrays.vertices,
                                                arrays.triangles.data(), arrays.faces, &settings,
                                                target_vertices, area_correct ? 1 : 0, &result)
                           : meromorph_remesh_d(arrays.doubles(), arrays.vertices,
                                                arrays.triangles.data(), arrays.faces, &settings,
                                                target_vertices, area_correct ? 1 : 0, &result);
  }
  std::unique_ptr<meromorph_remesh_result, void (*)(meromorph_remesh_result *)> owned(
      result, meromorph_remesh_free);
  relay.check(status);
  const auto n = py::ssize_t(meromorph_remesh_vertex_count(result));
  const auto m = py::ssize_t(meromorph_remesh_triangle_count(result));
  auto xyz = filled<double>({n, 3}), sphere = filled<double>({n, 3});
  auto triangles = filled<int32_t>({m, 3});
  auto layer = filled<int32_t>({n}), branch = filled<int32_t>({n});
  meromorph_remesh_mesh(result, xyz.mutable_data(), triangles.mutable_data(), layer.mutable_data(),
                        branch.mutable_data(), sphere.mutable_data());
  py::dict out;
  out["vertices"] = xyz, out["triangles"] = triangles, out["layer"] = layer;
  out["branch"] = branch, out["sphere"] = sphere;
  out["report"] = std::string(meromorph_remesh_report_json(result));
  out["summary"] = std::string(meromorph_remesh_summary(result));
  return out;
}

} // namespace

PYBIND11_MODULE(_native, module) {
  module.doc() = "meromorph's C library for Python (use the meromorph package, not this module)";
  native_error = PyErr_NewException("meromorph._native.NativeError", nullptr, nullptr);
  module.attr("NativeError") = py::reinterpret_borrow<py::object>(native_error);
  module.attr("version") = std::string(meromorph_version());
  module.attr("abi_version") = meromorph_abi_version();
  py::class_<Map>(module, "Map", "A map made by parameterize (opaque)");
  module.def("parameterize", &parameterize, py::arg("V"), py::arg("F"), py::arg("options"),
             py::arg("progress"));
  module.def("map_arrays", &map_arrays, py::arg("map"));
  module.def("write_map", &write_map, py::arg("map"), py::arg("surface"), py::arg("sphere"),
             py::arg("report"), py::arg("protected_paths"));
  module.def("read", &read_mesh, py::arg("path"));
  module.def("forms", &forms, py::arg("V"), py::arg("F"), py::arg("progress"));
  module.def("match", &match, py::arg("source_V"), py::arg("source_F"), py::arg("target_V"),
             py::arg("target_F"), py::arg("pairs"), py::arg("progress"));
  module.def("remesh", &remesh, py::arg("V"), py::arg("F"), py::arg("options"),
             py::arg("target_vertices"), py::arg("area_correct"), py::arg("progress"));
}
