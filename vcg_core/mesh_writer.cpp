#include "mesh_writer.h"

#include <cstdio>
#include <filesystem>

#include <vcg/complex/append.h>
#include <wrap/io_trimesh/export_obj.h>
#include <wrap/io_trimesh/export_off.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/export_stl.h>

#include "errors.h"
#include "mesh_format.h"

namespace meromorph {

void refuse_to_overwrite(const std::string &output, const std::vector<std::string> &inputs) {
  namespace fs = std::filesystem;
  std::error_code error;
  for (const std::string &input : inputs) {
    const bool same =
        fs::exists(output, error) && fs::exists(input, error)
            ? fs::equivalent(output, input, error)
            : fs::weakly_canonical(output, error) == fs::weakly_canonical(input, error);
    if (same)
      throw ArgumentError(output + ": this is the input file; meromorph never writes over its "
                                   "input, choose another output name");
  }
}

void write_mesh(const Mesh &mesh, const std::string &path, const WriteOptions &options,
                const std::vector<std::string> &protected_inputs) {
  refuse_to_overwrite(path, protected_inputs);
  const MeshFormat format = format_from_extension(path);
  Mesh &writable =
      const_cast<Mesh &>(mesh); // vcglib's exporters take non-const meshes; they only read.

  int mask = 0;
  if (options.vertex_texcoords) mask |= vcg::tri::io::Mask::IOM_VERTTEXCOORD;
  if (options.vertex_quality) mask |= vcg::tri::io::Mask::IOM_VERTQUALITY;
  if (options.wedge_texcoords) mask |= vcg::tri::io::Mask::IOM_WEDGTEXCOORD;

  // Write beside the target, then rename: a failed write never leaves a half file behind.
  const std::string temporary = path + ".meromorph-partial";
  int code = 0;
  switch (format) {
  case MeshFormat::ply: {
    vcg::tri::io::PlyInfo info;
    Mesh copy; // named attributes go on a copy: the caller's mesh is not changed
    const bool extra = !options.vertex_properties.empty() || options.vertex_texcoords;
    if (extra) vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, writable);
    if (options.vertex_texcoords) {
      // vcglib's PLY exporter writes double texture coordinates under a float header; write them
      // as the float properties texture_u, texture_v (the names MeshLab reads) instead.
      mask &= ~vcg::tri::io::Mask::IOM_VERTTEXCOORD;
      for (const char *name : {"texture_u", "texture_v"}) {
        auto handle = vcg::tri::Allocator<Mesh>::AddPerVertexAttribute<float>(copy, name);
        for (size_t v = 0; v < copy.vert.size(); ++v)
          handle[v] = float(name[8] == 'u' ? copy.vert[v].T().U() : copy.vert[v].T().V());
        info.AddPerVertexFloatAttribute(name);
      }
    }
    info.mask = mask;
    for (const VertexProperty &property : options.vertex_properties) {
      vcg::ply::PropDescriptor descriptor;
      descriptor.elemname = "vertex";
      descriptor.propname = property.name.c_str();
      descriptor.stotype1 = descriptor.memtype1 =
          property.byte ? vcg::ply::T_UCHAR : vcg::ply::T_INT;
      info.VertDescriptorVec.push_back(descriptor);
      info.VertAttrNameVec.push_back(property.name);
      if (property.byte) {
        auto handle =
            vcg::tri::Allocator<Mesh>::AddPerVertexAttribute<unsigned char>(copy, property.name);
        for (size_t v = 0; v < copy.vert.size(); ++v)
          handle[v] = (unsigned char)property.values.at(v);
      } else {
        auto handle = vcg::tri::Allocator<Mesh>::AddPerVertexAttribute<int>(copy, property.name);
        for (size_t v = 0; v < copy.vert.size(); ++v)
          handle[v] = property.values.at(v);
      }
    }
    code = vcg::tri::io::ExporterPLY<Mesh>::Save(extra ? copy : writable, temporary.c_str(),
                                                 options.binary, info);
    break;
  }
  case MeshFormat::obj:
    code = vcg::tri::io::ExporterOBJ<Mesh>::Save(writable, temporary.c_str(), mask);
    break;
  case MeshFormat::off:
    code = vcg::tri::io::ExporterOFF<Mesh>::Save(writable, temporary.c_str(), mask);
    break;
  case MeshFormat::stl:
    code = vcg::tri::io::ExporterSTL<Mesh>::Save(writable, temporary.c_str(), options.binary);
    break;
  }
  std::error_code error;
  if (code != 0) {
    std::filesystem::remove(temporary, error);
    throw InputError(path + ": could not be written (" + format_name(format) + " exporter error " +
                     std::to_string(code) + ")");
  }
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw InputError(path + ": could not be written (" + error.message() + ")");
  }
}

} // namespace meromorph
