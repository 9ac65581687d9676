#include "writers/atomic_write.hpp"

#include "core/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace finseg {

void write_file_atomically(const std::string& path, const std::string& content) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw OutputError("cannot write '" + path + "': it is a folder; name the file to write");
  }
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw OutputError("cannot open '" + partial + "' for writing: " + std::strerror(errno));
    }
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::remove(partial.c_str());
      throw OutputError("cannot write '" + partial + "' (disk full?)");
    }
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(partial.c_str());
    throw OutputError("cannot rename '" + partial + "' to '" + path + "': " + why);
  }
}

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw std::runtime_error("error while reading '" + path + "'");
  return ss.str();
}

}  // namespace finseg
