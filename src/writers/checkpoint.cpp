#include "writers/checkpoint.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "writers/atomic_write.hpp"
#include "writers/frame_file.hpp"

namespace finseg {
namespace {

using nlohmann::json;

// Recorded numbers may be NaN (JSON null).
double value(const json& v, const std::string& file, const std::string& field) {
  if (v.is_null()) return NAN;
  if (!v.is_number()) throw InputError(file, field, "expected a number");
  return v.get<double>();
}

const json& member(const json& obj, const std::string& key, const std::string& file,
                   const std::string& field) {
  if (!obj.is_object() || !obj.contains(key)) throw InputError(file, field + "." + key, "missing");
  return obj[key];
}

std::vector<double> numbers(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_array()) throw InputError(file, field, "expected an array");
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(value(v[i], file, fmt::format("{}[{}]", field, i)));
  return out;
}

Vec3 vec3(const json& v, const std::string& file, const std::string& field) {
  const std::vector<double> x = numbers(v, file, field);
  if (x.size() != 3) throw InputError(file, field, "expected 3 numbers");
  return {x[0], x[1], x[2]};
}

json pair_json(const PairSample& s) {
  const ContactPairForce& p = s.force;
  return {s.x,
          p.a,
          p.b,
          p.points,
          p.normal_force,
          p.friction_force,
          p.max_penetration,
          {p.f_b_W.x(), p.f_b_W.y(), p.f_b_W.z()}};
}

PairSample pair_from(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_array() || v.size() != 8) throw InputError(file, field, "expected 8 entries");
  PairSample s;
  s.x = value(v[0], file, field + "[0]");
  s.force.a = v[1].get<int>();
  s.force.b = v[2].get<int>();
  s.force.points = v[3].get<int>();
  s.force.normal_force = value(v[4], file, field + "[4]");
  s.force.friction_force = value(v[5], file, field + "[5]");
  s.force.max_penetration = value(v[6], file, field + "[6]");
  s.force.f_b_W = vec3(v[7], file, field + "[7]");
  return s;
}

std::vector<Vec3> vec3s_from(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_array()) throw InputError(file, field, "expected an array");
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(vec3(v[i], file, fmt::format("{}[{}]", field, i)));
  return out;
}

// Arrays added after the first checkpoints may be absent: they are then left empty.
Frame frame_from(const json& v, const std::string& file, const std::string& field) {
  Frame f;
  f.t = value(member(v, "t", file, field), file, field + ".t");
  const json& r = member(v, "R_WB", file, field);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::vector<double> x = numbers(r[i], file, fmt::format("{}.R_WB[{}]", field, i));
    if (x.size() != 9) throw InputError(file, fmt::format("{}.R_WB[{}]", field, i), "expected 9");
    f.R_WB.push_back(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(x.data()));
  }
  f.p_W = vec3s_from(member(v, "p_W_m", file, field), file, field + ".p_W_m");
  f.contact_points_W =
      vec3s_from(member(v, "contact_points_W_m", file, field), file, field + ".contact_points_W_m");
  visit_frame_vectors(f, [&](const char* key, std::vector<Vec3>& out) {
    if (v.contains(key)) out = vec3s_from(v[key], file, field + "." + key);
  });
  visit_frame_arrays(f, [&](const char* key, std::vector<double>& out) {
    if (v.contains(key)) out = numbers(v[key], file, field + "." + key);
  });
  return f;
}

json recorded_json(const RunRecorder& rec) {
  json tables = json::array();
  for (const ProbeTable& t : rec.tables()) {
    json pairs = json::array();
    for (const PairSample& s : t.pair_rows) pairs.push_back(pair_json(s));
    tables.push_back({{"name", t.name}, {"rows", t.rows}, {"pair_rows", pairs}});
  }
  json samples = json::array();
  for (const PhaseSample& p : rec.phase_samples())
    samples.push_back({p.displacement, p.active_contacts, p.bend});
  return {{"outputs", rec.outputs()},
          {"last_abscissa", rec.last_abscissa()},
          {"tables", tables},
          {"phase_samples", samples}};
}

// The frames of a checkpoint: in its frame file, or (checkpoints written before 2026-11-29) in
// `run.frames`.
std::vector<Frame> restore_frames(const json& j, const std::string& file,
                                  const std::string& run_hash) {
  std::vector<Frame> frames;
  if (j.contains("frames_file")) {
    const json& ff = j["frames_file"];
    const json& count = member(ff, "count", file, "run.frames_file");
    const json& bytes = member(ff, "bytes", file, "run.frames_file");
    if (!count.is_number_unsigned() || !bytes.is_number_unsigned())
      throw InputError(file, "run.frames_file", "expected counts");
    const std::string path =
        (std::filesystem::path(file).parent_path() / kCheckpointFramesFile).string();
    return read_frame_file(path, run_hash, count.get<std::size_t>(), bytes.get<std::uint64_t>());
  }
  const json& jf = member(j, "frames", file, "run");
  for (std::size_t i = 0; i < jf.size(); ++i)
    frames.push_back(frame_from(jf[i], file, fmt::format("run.frames[{}]", i)));
  return frames;
}

void restore_recorded(const json& j, const std::string& file, const std::string& run_hash,
                      RunRecorder& rec) {
  const std::string run = "run";
  std::vector<ProbeTable> tables = rec.tables();
  const json& jt = member(j, "tables", file, run);
  if (!jt.is_array() || jt.size() != tables.size())
    throw InputError(file, "run.tables", fmt::format("expected {} probes", tables.size()));
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const std::string f = fmt::format("run.tables[{}]", k);
    if (member(jt[k], "name", file, f) != tables[k].name)
      throw InputError(file, f + ".name", "expected probe \"" + tables[k].name + "\"");
    const json& rows = member(jt[k], "rows", file, f);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      tables[k].rows.push_back(numbers(rows[r], file, fmt::format("{}.rows[{}]", f, r)));
      if (tables[k].rows.back().size() != tables[k].columns.size())
        throw InputError(file, fmt::format("{}.rows[{}]", f, r),
                         fmt::format("expected {} columns", tables[k].columns.size()));
    }
    const json& pairs = member(jt[k], "pair_rows", file, f);
    for (std::size_t r = 0; r < pairs.size(); ++r)
      tables[k].pair_rows.push_back(
          pair_from(pairs[r], file, fmt::format("{}.pair_rows[{}]", f, r)));
  }
  std::vector<Frame> frames = restore_frames(j, file, run_hash);
  std::vector<PhaseSample> samples;
  const json& js = member(j, "phase_samples", file, run);
  for (std::size_t i = 0; i < js.size(); ++i) {
    const std::vector<double> x = numbers(js[i], file, fmt::format("run.phase_samples[{}]", i));
    if (x.size() != 3)
      throw InputError(file, fmt::format("run.phase_samples[{}]", i), "expected 3");
    samples.push_back({x[0], static_cast<int>(x[1]), x[2]});
  }
  const json& outputs = member(j, "outputs", file, run);
  if (!outputs.is_number_unsigned()) throw InputError(file, "run.outputs", "expected a count");
  rec.restore(std::move(tables), std::move(frames), std::move(samples),
              value(member(j, "last_abscissa", file, run), file, "run.last_abscissa"),
              outputs.get<std::size_t>());
}

}  // namespace

void write_checkpoint(const std::string& dir, const Model& model, const StateSnapshot& snapshot,
                      const RunRecorder& rec) {
  json j = state_json(model, snapshot);
  j["run"] = recorded_json(rec);
  // The frames go to their own file first, so that the checkpoint never names frames that are
  // not there.
  if (rec.frames().empty()) {
    j["run"]["frames"] = json::array();
  } else {
    const std::string frames = (std::filesystem::path(dir) / kCheckpointFramesFile).string();
    j["run"]["frames_file"] = {
        {"count", rec.frames().size()},
        {"bytes", sync_frame_file(frames, snapshot.scene_hash, rec.frames())}};
  }
  write_file_atomically((std::filesystem::path(dir) / kCheckpointFile).string(),
                        j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

StateSnapshot read_checkpoint(const std::string& path, const Model& model, RunRecorder& rec) {
  json j;
  try {
    j = json::parse(read_whole_file(path));
  } catch (const json::exception& e) {
    throw InputError(path, "(file)", std::string("not valid JSON: ") + e.what());
  }
  StateSnapshot snap = parse_state_json(j, model, path);
  if (!j.contains("run")) throw InputError(path, "run", "missing (a state file, not a checkpoint)");
  restore_recorded(j["run"], path, snap.scene_hash, rec);
  return snap;
}

}  // namespace finseg
