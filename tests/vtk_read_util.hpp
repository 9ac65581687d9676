// Reads back the VTK files finseg writes: DataArray tags in the XML part and their binary
// appended, zlib-compressed bytes (VTK's block header, UInt64), decoded independently of the
// writer with zlib's uncompress.
#pragma once

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace finseg::vtk_read {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Attribute `name` of the tag that starts at or before `at` and ends at the next '>'.
inline std::string tag_attr(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t a = tag.find(key);
  if (a == std::string::npos) return "";
  const std::size_t b = tag.find('"', a + key.size());
  return tag.substr(a + key.size(), b - a - key.size());
}

/// Uncompressed bytes of the block-compressed stream at `p` (header: blocks, block size,
/// last partial size, compressed sizes; all UInt64).
inline std::string inflate_blocks(const char* p) {
  std::uint64_t h[3];
  std::memcpy(h, p, sizeof h);
  std::vector<std::uint64_t> sizes(h[0]);
  std::memcpy(sizes.data(), p + 24, 8 * h[0]);
  const char* data = p + 24 + 8 * h[0];
  std::string out;
  for (std::uint64_t b = 0; b < h[0]; ++b) {
    uLongf len = (b + 1 == h[0] && h[2] != 0) ? h[2] : h[1];
    std::string block(len, '\0');
    if (uncompress(reinterpret_cast<Bytef*>(block.data()), &len,
                   reinterpret_cast<const Bytef*>(data), sizes[b]) != Z_OK) {
      throw std::runtime_error("zlib block does not inflate");
    }
    out.append(block.data(), len);
    data += sizes[b];
  }
  return out;
}

/// Values of the appended DataArray `name` of a .vtu as doubles (empty if absent);
/// `components` receives NumberOfComponents.
inline std::vector<double> array(const std::string& vtu, const std::string& name,
                                 int* components = nullptr) {
  const std::size_t appended = vtu.find("<AppendedData encoding=\"raw\">");
  if (appended == std::string::npos) throw std::runtime_error("no raw appended data");
  const std::size_t at = vtu.find("Name=\"" + name + "\"");
  if (at == std::string::npos || at > appended) return {};
  const std::size_t start = vtu.rfind('<', at);
  const std::string tag = vtu.substr(start, vtu.find('>', at) - start + 1);
  if (tag_attr(tag, "format") != "appended") throw std::runtime_error("not appended: " + name);
  if (components) *components = std::stoi(tag_attr(tag, "NumberOfComponents"));
  const std::size_t base = vtu.find('_', appended) + 1;
  const std::string bytes =
      inflate_blocks(vtu.data() + base + std::stoull(tag_attr(tag, "offset")));
  const std::string type = tag_attr(tag, "type");
  std::vector<double> v;
  auto take = [&](auto zero) {
    using T = decltype(zero);
    for (std::size_t k = 0; k + sizeof(T) <= bytes.size(); k += sizeof(T)) {
      T x;
      std::memcpy(&x, bytes.data() + k, sizeof(T));
      v.push_back(static_cast<double>(x));
    }
  };
  if (type == "Float64")
    take(double{});
  else if (type == "Int64")
    take(std::int64_t{});
  else if (type == "Int32")
    take(std::int32_t{});
  else if (type == "UInt8")
    take(std::uint8_t{});
  else
    throw std::runtime_error("unexpected type " + type);
  return v;
}

}  // namespace finseg::vtk_read
