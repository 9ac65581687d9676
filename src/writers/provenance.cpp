#include "writers/provenance.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "core/blas_kernels.hpp"
#include "core/version.hpp"
#include "elements/crease_law.hpp"
#include "scene/state_file.hpp"
#include "writers/atomic_write.hpp"

namespace finseg {

std::string sha256_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read for its hash");
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(),
                                                                    &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 unavailable (OpenSSL)");
  }
  std::vector<char> buf(1 << 16);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    EVP_DigestUpdate(ctx.get(), buf.data(), static_cast<std::size_t>(in.gcount()));
  }
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  EVP_DigestFinal_ex(ctx.get(), md, &len);
  std::string hex;
  for (unsigned int i = 0; i < len; ++i) hex += fmt::format("{:02x}", md[i]);
  return hex;
}

std::string utc_now_iso8601() {
  const auto now = std::chrono::floor<std::chrono::seconds>(std::chrono::system_clock::now());
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", now);
}

namespace {

// {file, sha256}; sha256 null when the file cannot be read (a scene parsed from text).
nlohmann::json hashed(const std::string& file) {
  try {
    return {{"file", file}, {"sha256", sha256_file(file)}};
  } catch (const std::runtime_error&) {
    return {{"file", file}, {"sha256", nullptr}};
  }
}

}  // namespace

std::vector<std::string> scene_data_files(const Scene& scene) {
  std::vector<std::string> files;
  if (!scene.pattern_file.empty()) files.push_back(scene.pattern_file);
  for (const CreaseDef& c : scene.model.creases) {
    if (!c.law) continue;
    for (const std::string& f : c.law->data_files()) {
      if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
    }
  }
  return files;
}

std::string scene_inputs_hash(const std::string& scene_text, const Scene& scene) {
  std::string inputs = scene_text;
  for (const std::string& f : scene_data_files(scene)) inputs += read_whole_file(f);
  for (const Override& v : scene.overrides) inputs += "\n--set " + v.path + "=" + v.value;
  return scene_hash(inputs);
}

nlohmann::json provenance_json(const Scene& scene) {
  nlohmann::json data = nlohmann::json::array();
  for (const std::string& f : scene_data_files(scene)) data.push_back(hashed(f));
  nlohmann::json j = {{"finseg_version", version()},
                      {"git_revision", git_revision()},
                      {"blas_kernels", blas_kernels()},
                      {"date_utc", utc_now_iso8601()},
                      {"scene", hashed(scene.file)},
                      {"data_files", data},
                      {"hash", "SHA-256 of the file's bytes (OpenSSL libcrypto)"}};
  if (!scene.start_state.empty()) j["start_state"] = hashed(scene.start_state);
  return j;
}

}  // namespace finseg
