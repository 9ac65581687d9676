#include "writers/output_folder.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "probes/recorder.hpp"
#include "writers/atomic_write.hpp"
#include "writers/unfolding_outputs.hpp"

namespace finseg {
namespace {

namespace fs = std::filesystem;

// Length of the UTF-8 sequence starting with `c` (0: not a valid lead byte).
int sequence_length(unsigned char c) {
  if (c < 0x80) return 1;
  if (c >= 0xc2 && c <= 0xdf) return 2;
  if (c >= 0xe0 && c <= 0xef) return 3;
  if (c >= 0xf0 && c <= 0xf4) return 4;
  return 0;
}

void check_text(const std::string& text, const std::string& file, const std::string& field) {
  if (!is_valid_utf8(text)) throw InputError(file, field, "is not valid UTF-8 text");
}

void check_name(const std::string& name, const std::string& file, const std::string& field) {
  check_text(name, file, field);
  if (name.empty() || name == "." || name == "..")
    throw InputError(file, field, "a probe name becomes a file name: must not be empty, . or ..");
  if (name.size() > kMaxNameBytes) {
    throw InputError(file, field,
                     fmt::format("is {} bytes long; a probe name becomes a file name: at most {}",
                                 name.size(), kMaxNameBytes));
  }
  for (unsigned char c : name) {
    if (c == '/' || c == '\\' || c < 0x20 || c == 0x7f) {
      throw InputError(file, field,
                       "a probe name becomes a file name: no '/', '\\', NUL or control characters");
    }
  }
}

// Every file name the run will write (except VTK frames), with the field it comes from.
void check_file_names(const Scene& scene) {
  std::set<std::string> names{"summary.json", "checkpoint.json", "manifest.json", "animation.html"};
  if (scene.outputs.phases.enabled) names.insert("phases.csv");
  const auto add = [&](const std::string& name, std::size_t k) {
    if (!names.insert(name).second) {
      throw InputError(scene.file, fmt::format("probes[{}].name", k),
                       fmt::format("its output file {} is also another output's", name));
    }
  };
  for (std::size_t k = 0; k < scene.model.probes.size(); ++k) {
    const ProbeDef& p = scene.model.probes[k];
    check_name(p.name, scene.file, fmt::format("probes[{}].name", k));
    add(p.name + ".csv", k);
    if (p.pairs) add(p.name + "_pairs.csv", k);
    const bool plotted =
        p.kind == ProbeKind::Drive || p.kind == ProbeKind::Shape || p.kind == ProbeKind::Unfolding;
    if (scene.outputs.plot && plotted) add(p.name + ".png", k);
    if (p.kind == ProbeKind::Unfolding) {
      add(unfolding_order_file(p.name), k);
      if (scene.outputs.plot) add(unfolding_map_file(p.name), k);
    }
  }
  // Each chamber's table (probes/recorder.hpp): chamber_<name>.csv and .png.
  for (std::size_t c = 0; c < scene.model.chambers.size(); ++c) {
    const std::string field = fmt::format("chambers[{}].name", c);
    const std::string stem = chamber_table_name(scene.model.chambers[c]);
    check_name(stem, scene.file, field);
    for (const std::string& file : {stem + ".csv", stem + ".png"}) {
      if (file.ends_with(".png") && !scene.outputs.plot) continue;
      if (!names.insert(file).second) {
        throw InputError(scene.file, field,
                         fmt::format("its output file {} is also another output's", file));
      }
    }
  }
}

// Creates and removes a file in `dir`: the only sure test that the run can write there.
void check_writable(const std::string& dir) {
  const fs::path probe = fs::path(dir) / fmt::format(".finseg-write-test-{}", ::getpid());
  std::ofstream out(probe);
  out << "finseg\n";
  out.close();
  const bool ok = !out.fail();
  std::error_code ec;
  fs::remove(probe, ec);
  if (!ok) throw InputError(dir, "--out", "cannot write files in this folder");
}

// A manifest entry is a relative path inside the folder: no absolute path, no "..".
bool inside(const std::string& entry) {
  const fs::path p(entry);
  if (entry.empty() || p.is_absolute()) return false;
  for (const fs::path& part : p) {
    if (part == "..") return false;
  }
  return true;
}

}  // namespace

bool is_valid_utf8(const std::string& text) {
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const int len = sequence_length(s[i]);
    if (len == 0 || i + len > n) return false;
    for (int k = 1; k < len; ++k) {
      if ((s[i + k] & 0xc0) != 0x80) return false;
    }
    // Overlong three/four-byte forms, UTF-16 surrogates and code points above U+10FFFF.
    if (len == 3 && s[i] == 0xe0 && s[i + 1] < 0xa0) return false;
    if (len == 3 && s[i] == 0xed && s[i + 1] >= 0xa0) return false;
    if (len == 4 && s[i] == 0xf0 && s[i + 1] < 0x90) return false;
    if (len == 4 && s[i] == 0xf4 && s[i + 1] >= 0x90) return false;
    i += len;
  }
  return true;
}

void check_output_folder(const std::string& dir, const Scene& scene) {
  if (dir.empty()) throw InputError("<cli>", "--out", "must name a folder (it is empty)");
  check_text(dir, "<cli>", "--out");
  check_text(scene.file, scene.file, "(file name)");
  check_text(scene.title, scene.file, "title");
  for (std::size_t i = 0; i < scene.model.bodies.size(); ++i)
    check_text(scene.model.bodies[i].name, scene.file, fmt::format("bodies[{}].name", i));
  check_file_names(scene);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError(dir, "--out",
                     "cannot create the output folder" + (ec ? ": " + ec.message() : ""));
  }
  check_writable(dir);
}

void remove_previous_run(const std::string& dir, const std::vector<std::string>& keep) {
  const fs::path manifest = fs::path(dir) / kManifestFile;
  if (!fs::exists(manifest)) return;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_whole_file(manifest.string()));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(manifest.string(), "(file)",
                     std::string("not valid JSON (remove it by hand): ") + e.what());
  }
  if (!j.contains("files") || !j["files"].is_array())
    throw InputError(manifest.string(), "files", "missing (remove the manifest by hand)");
  std::set<fs::path> folders;
  for (const auto& entry : j["files"]) {
    if (!entry.is_string() || !inside(entry.get<std::string>())) continue;
    const std::string name = entry.get<std::string>();
    if (std::find(keep.begin(), keep.end(), name) != keep.end()) continue;
    const fs::path p = fs::path(dir) / name;
    std::error_code ec;
    if (fs::is_regular_file(fs::symlink_status(p, ec))) fs::remove(p, ec);
    if (p.parent_path() != fs::path(dir)) folders.insert(p.parent_path());
  }
  for (const fs::path& f : folders) {
    std::error_code ec;
    if (fs::is_directory(f, ec) && fs::is_empty(f, ec)) fs::remove(f, ec);
  }
}

void write_manifest(const std::string& dir, const std::vector<std::string>& files) {
  std::set<std::string> list;
  for (const std::string& f : files) {
    list.insert(f);
    // Files written beside an entry (a plot's .dat and .gp): "<entry>.*"; the VTK series:
    // every "frames*" file in vtk/.
    const fs::path p = fs::path(dir) / f;
    const bool vtk = f == "vtk/frames.pvd";
    const std::string prefix = vtk ? "frames" : p.filename().string() + ".";
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(p.parent_path(), ec)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() && name.rfind(prefix, 0) == 0)
        list.insert(
            fs::path(f).parent_path().empty() ? name : (fs::path(f).parent_path() / name).string());
    }
  }
  list.erase(kManifestFile);
  std::vector<std::string> sorted(list.begin(), list.end());
  sorted.push_back(kManifestFile);
  const nlohmann::json j{{"written_by", "finseg run"}, {"files", sorted}};
  write_file_atomically((fs::path(dir) / kManifestFile).string(), j.dump(1) + "\n");
}

}  // namespace finseg
