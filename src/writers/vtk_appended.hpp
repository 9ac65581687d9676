// Binary appended data of VTK XML files, zlib-compressed in VTK's block format
// (compressor="vtkZLibDataCompressor", header_type="UInt64"): the arrays' bytes go after the
// XML in one <AppendedData encoding="raw"> section, each DataArray tag names its offset.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace finseg {

/// Compresses `bytes` as VTK does: a header of UInt64 [blocks, block size, size of the
/// last block if partial else 0, compressed size of each block], then the zlib streams.
std::string vtk_zlib_block(const std::string& bytes, std::size_t block_size = 32768);

/// Collects the arrays of one file and writes their DataArray tags and the appended section.
class VtkAppended {
 public:
  /// DataArray tag for `values` (type "Float64", "Int64", "Int32" or "UInt8" to match T),
  /// `components` per tuple, its compressed bytes added to the appended section.
  template <class T>
  std::string array(const char* type, const std::string& name, int components,
                    const std::vector<T>& values) {
    return tag(
        type, name, components,
        std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
  }
  /// The <AppendedData> section (after </UnstructuredGrid>, before </VTKFile>).
  std::string section() const;

 private:
  std::string tag(const char* type, const std::string& name, int components,
                  const std::string& bytes);
  std::string data_;
};

/// Attributes of the <VTKFile> tag that declare the compression.
inline const char* kVtkCompressor = "compressor=\"vtkZLibDataCompressor\"";

}  // namespace finseg
