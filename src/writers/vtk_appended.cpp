#include "writers/vtk_appended.hpp"

#include <zlib.h>

#include <bit>
#include <stdexcept>

#include <fmt/format.h>

namespace finseg {
namespace {

static_assert(std::endian::native == std::endian::little, "the files declare LittleEndian");

void append_u64(std::string& out, std::uint64_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

std::string vtk_zlib_block(const std::string& bytes, std::size_t block_size) {
  const std::size_t n = bytes.size();
  const std::size_t blocks = (n + block_size - 1) / block_size;
  std::string header, body;
  append_u64(header, blocks);
  append_u64(header, block_size);
  append_u64(header, n % block_size);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t len = std::min(block_size, n - b * block_size);
    uLongf out_len = compressBound(len);
    std::string out(out_len, '\0');
    // The fastest level: doubles of positions hardly compress (an 11 200-segment frame 8.6 ->
    // 6.6 MB at level 1 and at the default 6) and level 6 took 1.7 times as long.
    const int rc =
        compress2(reinterpret_cast<Bytef*>(out.data()), &out_len,
                  reinterpret_cast<const Bytef*>(bytes.data() + b * block_size), len, Z_BEST_SPEED);
    if (rc != Z_OK) throw std::runtime_error(fmt::format("zlib compress2 failed ({})", rc));
    append_u64(header, out_len);
    body.append(out.data(), out_len);
  }
  return header + body;
}

std::string VtkAppended::tag(const char* type, const std::string& name, int components,
                             const std::string& bytes) {
  const std::string t = fmt::format(
      "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
      "offset=\"{}\"/>\n",
      type, name, components, data_.size());
  data_ += vtk_zlib_block(bytes);
  return t;
}

std::string VtkAppended::section() const {
  return "  <AppendedData encoding=\"raw\">\n   _" + data_ + "\n  </AppendedData>\n";
}

}  // namespace finseg
