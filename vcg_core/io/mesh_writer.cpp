#include "io/mesh_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <vcg/complex/append.h>
#include <wrap/io_trimesh/export_obj.h>
#include <wrap/io_trimesh/export_off.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/export_stl.h>

#include "common/errors.h"
#include "io/mesh_format.h"
#include "io/staged_outputs.h"

namespace meromorph {

namespace {

// A PLY file with the extra per-vertex properties of `options` (texture coordinates as the float
// properties texture_u, texture_v; integer, byte and float properties by name), on a copy of the
// mesh where there are any: the caller's mesh is not changed. Returns vcglib's code.
int save_ply(Mesh &writable, const std::string &file, const WriteOptions &options, int mask) {
  vcg::tri::io::PlyInfo info;
  Mesh copy;
  const bool extra = !options.vertex_properties.empty() ||
                     !options.float_vertex_properties.empty() || options.vertex_texcoords;
  if (extra) vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, writable);
  // Every extra property is described here (with names that outlive the save), so nothing is
  // allocated for the exporter to leak.
  auto describe = [&](const char *name, int type) {
    vcg::ply::PropDescriptor descriptor;
    descriptor.elemname = "vertex";
    descriptor.propname = name;
    descriptor.stotype1 = descriptor.memtype1 = type;
    info.VertDescriptorVec.push_back(descriptor);
    info.VertAttrNameVec.push_back(name);
  };
  auto add = [&](const std::string &name, auto type_tag, auto value_of) {
    using T = decltype(type_tag);
    auto handle = vcg::tri::Allocator<Mesh>::AddPerVertexAttribute<T>(copy, name);
    for (size_t v = 0; v < copy.vert.size(); ++v)
      handle[v] = T(value_of(v));
  };
  if (options.vertex_texcoords) {
    // vcglib's PLY exporter writes double texture coordinates under a float header; write them
    // as the float properties texture_u, texture_v (the names MeshLab reads) instead.
    mask &= ~vcg::tri::io::Mask::IOM_VERTTEXCOORD;
    for (const char *name : {"texture_u", "texture_v"}) {
      add(name, float(),
          [&](size_t v) { return name[8] == 'u' ? copy.vert[v].T().U() : copy.vert[v].T().V(); });
      describe(name, vcg::ply::T_FLOAT);
    }
  }
  info.mask = mask;
  for (const VertexProperty &property : options.vertex_properties) {
    describe(property.name.c_str(), property.byte ? vcg::ply::T_UCHAR : vcg::ply::T_INT);
    const auto value = [&](size_t v) { return property.values.at(v); };
    if (property.byte)
      add(property.name, (unsigned char)0, value);
    else
      add(property.name, int(), value);
  }
  for (const FloatVertexProperty &property : options.float_vertex_properties) {
    describe(property.name.c_str(), vcg::ply::T_FLOAT);
    add(property.name, float(), [&](size_t v) { return property.values.at(v); });
  }
  const int code = vcg::tri::io::ExporterPLY<Mesh>::Save(extra ? copy : writable, file.c_str(),
                                                         options.binary, info);
  copy.ClearAttributes();
  return code;
}

} // namespace

void save_mesh(const Mesh &mesh, MeshFormat format, const std::string &file,
               const WriteOptions &options) {
  Mesh &writable =
      const_cast<Mesh &>(mesh); // vcglib's exporters take non-const meshes; they only read.
  int mask = 0;
  if (options.vertex_texcoords) mask |= vcg::tri::io::Mask::IOM_VERTTEXCOORD;
  if (options.vertex_quality) mask |= vcg::tri::io::Mask::IOM_VERTQUALITY;
  if (options.wedge_texcoords) mask |= vcg::tri::io::Mask::IOM_WEDGTEXCOORD;
  errno = 0;
  int code = 0;
  switch (format) {
  case MeshFormat::ply:
    code = save_ply(writable, file, options, mask);
    break;
  case MeshFormat::obj:
    code = vcg::tri::io::ExporterOBJ<Mesh>::Save(writable, file.c_str(), mask);
    break;
  case MeshFormat::off:
    code = vcg::tri::io::ExporterOFF<Mesh>::Save(writable, file.c_str(), mask);
    break;
  case MeshFormat::stl:
    code = vcg::tri::io::ExporterSTL<Mesh>::Save(writable, file.c_str(), options.binary);
    break;
  }
  if (code != 0) {
    const std::string reason =
        errno ? std::strerror(errno)
              : std::string(format_name(format)) + " exporter error " + std::to_string(code);
    std::remove(file.c_str());
    throw WriteError(file + ": could not be written (" + reason + ")");
  }
}

void write_mesh(const Mesh &mesh, const std::string &path, const WriteOptions &options,
                const std::vector<std::string> &protected_inputs) {
  const MeshFormat format = output_format(path);
  StagedOutputs outputs(protected_inputs);
  const std::string temporary = outputs.add(path);
  outputs.writing([&] {
    save_mesh(mesh, format, temporary, options);
    outputs.commit();
  });
}

} // namespace meromorph
