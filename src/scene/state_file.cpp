#include "scene/state_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "writers/atomic_write.hpp"

namespace finseg {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "finseg-state";
constexpr int kVersion = 1;

json vec_json(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

json mat_json(const Mat3& m) {  // row-major
  json a = json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a.push_back(m(r, c));
  return a;
}

json vecs_json(const std::vector<Vec3>& vs) {
  json a = json::array();
  for (const Vec3& v : vs) a.push_back(vec_json(v));
  return a;
}

json mats_json(const std::vector<Mat3>& ms) {
  json a = json::array();
  for (const Mat3& m : ms) a.push_back(mat_json(m));
  return a;
}

json contact_json(const ContactState& c) {
  json anchors = json::array();
  for (const ContactAnchor& a : c.anchors) {
    anchors.push_back({{"key", a.key},
                       {"r_src_B_m", vec_json(a.r_src_B)},
                       {"r_tgt_B_m", vec_json(a.r_tgt_B)},
                       {"impact_speed_m_s", a.impact_speed},
                       {"slip_speed_m_s", a.slip_speed},
                       {"overlap_m", a.overlap},
                       {"side", a.side},
                       {"sliding", a.sliding}});
  }
  return {{"anchors", anchors}, {"p_W_m", vecs_json(c.p_W)}, {"R_WB", mats_json(c.R_WB)}};
}

// Reading: every accessor names the file and the dotted field in its error.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(file_, field, what);
  }
  const json& key(const json& obj, const std::string& name, const std::string& field) const {
    if (!obj.is_object()) fail(field, "expected an object");
    const auto it = obj.find(name);
    if (it == obj.end()) fail(join(field, name), "missing");
    return *it;
  }
  const json& array(const json& v, const std::string& field, std::size_t size) const {
    if (!v.is_array()) fail(field, "expected an array");
    if (v.size() != size) fail(field, fmt::format("expected {} entries, found {}", size, v.size()));
    return v;
  }
  double number(const json& v, const std::string& field) const {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(field, "expected a finite number");
    return v.get<double>();
  }
  long integer(const json& v, const std::string& field) const {
    if (!v.is_number_integer()) fail(field, "expected an integer");
    return v.get<long>();
  }
  bool boolean(const json& v, const std::string& field) const {
    if (!v.is_boolean()) fail(field, "expected true or false");
    return v.get<bool>();
  }
  Vec3 vec(const json& v, const std::string& field) const {
    array(v, field, 3);
    return {number(v[0], field + "[0]"), number(v[1], field + "[1]"), number(v[2], field + "[2]")};
  }
  Mat3 rotation(const json& v, const std::string& field) const {
    array(v, field, 9);
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = number(v[k], fmt::format("{}[{}]", field, k));
    if ((m.transpose() * m - Mat3::Identity()).lpNorm<Eigen::Infinity>() > 1e-9 ||
        m.determinant() < 0) {
      fail(field, "not a rotation matrix (9 numbers, row by row, orthonormal, det +1)");
    }
    return m;
  }
  std::vector<Vec3> vecs(const json& v, const std::string& field, std::size_t size) const {
    array(v, field, size);
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < size; ++i)
      out.push_back(vec(v[i], fmt::format("{}[{}]", field, i)));
    return out;
  }
  static std::string join(const std::string& field, const std::string& name) {
    return field.empty() ? name : field + "." + name;
  }

 private:
  std::string file_;
};

void read_bodies(const Reader& in, const json& j, std::size_t n, State& s) {
  const json& bodies = in.array(in.key(j, "bodies", ""), "bodies", n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string f = fmt::format("bodies[{}]", i);
    s.p_W.push_back(in.vec(in.key(bodies[i], "p_W_m", f), f + ".p_W_m"));
    s.R_WB.push_back(in.rotation(in.key(bodies[i], "R_WB", f), f + ".R_WB"));
    s.v_W.push_back(in.vec(in.key(bodies[i], "v_W_m_s", f), f + ".v_W_m_s"));
    s.w_W.push_back(in.vec(in.key(bodies[i], "w_W_rad_s", f), f + ".w_W_rad_s"));
  }
}

void read_elements(const Reader& in, const json& j, std::size_t n, State& s) {
  const json& elements = in.array(in.key(j, "elements", ""), "elements", n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string f = fmt::format("elements[{}]", k);
    ElementHistory h;
    h.fold_angle = in.number(in.key(elements[k], "fold_angle_rad", f), f + ".fold_angle_rad");
    const long openings = in.integer(in.key(elements[k], "openings", f), f + ".openings");
    if (openings < 0 || openings > 1000000) in.fail(f + ".openings", "expected 0..1000000");
    h.openings = static_cast<int>(openings);
    h.opened = in.boolean(in.key(elements[k], "opened", f), f + ".opened");
    // Optional: states written before the key existed continue from log R_FE.
    if (elements[k].contains("rotation_F_rad"))
      h.rotation_F = in.vec(elements[k]["rotation_F_rad"], f + ".rotation_F_rad");
    s.history.push_back(h);
  }
}

void read_contact(const Reader& in, const json& j, std::size_t bodies, State& s) {
  const json& c = in.key(j, "contact", "");
  const json& anchors = in.key(c, "anchors", "contact");
  if (!anchors.is_array()) in.fail("contact.anchors", "expected an array");
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    const std::string f = fmt::format("contact.anchors[{}]", i);
    const json& a = anchors[i];
    ContactAnchor x;
    const json& key = in.key(a, "key", f);
    if (!key.is_number_unsigned()) in.fail(f + ".key", "expected an unsigned integer");
    x.key = key.get<std::uint64_t>();
    if (i > 0 && x.key <= s.contact.anchors.back().key) in.fail(f + ".key", "keys must ascend");
    x.r_src_B = in.vec(in.key(a, "r_src_B_m", f), f + ".r_src_B_m");
    x.r_tgt_B = in.vec(in.key(a, "r_tgt_B_m", f), f + ".r_tgt_B_m");
    x.impact_speed = in.number(in.key(a, "impact_speed_m_s", f), f + ".impact_speed_m_s");
    // Optional: states written before the key existed continue with the exact law.
    if (a.contains("slip_speed_m_s")) {
      x.slip_speed = in.number(a["slip_speed_m_s"], f + ".slip_speed_m_s");
      if (x.slip_speed < 0 && x.slip_speed != -1)
        in.fail(f + ".slip_speed_m_s", "expected -1 (not known) or a speed >= 0");
    }
    if (a.contains("overlap_m")) {  // optional: absent, no overlap
      x.overlap = in.number(a["overlap_m"], f + ".overlap_m");
      if (!(x.overlap >= 0)) in.fail(f + ".overlap_m", "expected a penetration >= 0 m");
    }
    const long side = in.integer(in.key(a, "side", f), f + ".side");
    if (side != 1 && side != -1 && side != 0)
      in.fail(f + ".side", "expected 1, -1 or 0 (an overlapping point with no side yet)");
    x.side = static_cast<int>(side);
    x.sliding = in.boolean(in.key(a, "sliding", f), f + ".sliding");
    s.contact.anchors.push_back(x);
  }
  // The poses of the last contact commit: none yet, or one per body.
  const json& p = in.key(c, "p_W_m", "contact");
  const std::size_t n = p.is_array() && p.empty() ? 0 : bodies;
  s.contact.p_W = in.vecs(p, "contact.p_W_m", n);
  const json& r = in.array(in.key(c, "R_WB", "contact"), "contact.R_WB", n);
  for (std::size_t i = 0; i < n; ++i)
    s.contact.R_WB.push_back(in.rotation(r[i], fmt::format("contact.R_WB[{}]", i)));
}

// The gas of each chamber (docs/gas.md): keys with their units, one object per chamber.
constexpr std::array<std::pair<const char*, double ChamberGas::*>, 9> kGasKeys{{
    {"t", &ChamberGas::t},
    {"mass_kg", &ChamberGas::mass},
    {"energy_J", &ChamberGas::energy},
    {"volume_m3", &ChamberGas::volume},
    {"pressure_Pa", &ChamberGas::pressure},
    {"temperature_K", &ChamberGas::temperature},
    {"work_J", &ChamberGas::work},
    {"injected_kg", &ChamberGas::injected},
    {"vented_kg", &ChamberGas::vented},
}};

json chambers_json(const Model& model, const State& s) {
  json out = json::array();
  for (std::size_t c = 0; c < s.chambers.size(); ++c) {
    json g = {{"name", model.chambers[c].name}};
    for (const auto& [key, member] : kGasKeys) g[key] = s.chambers[c].*member;
    out.push_back(g);
  }
  return out;
}

// Required when the model has chambers (a state without its gas would restart it).
void read_chambers(const Reader& in, const json& j, const Model& model, State& s) {
  const std::size_t n = model.chambers.size();
  if (n == 0) return;
  const json& arr = in.array(in.key(j, "chambers", ""), "chambers", n);
  for (std::size_t c = 0; c < n; ++c) {
    const std::string f = fmt::format("chambers[{}]", c);
    ChamberGas g;
    for (const auto& [key, member] : kGasKeys) {
      g.*member = in.number(in.key(arr[c], key, f), f + "." + key);
      // Everything but the work is a mass, energy or state variable that cannot be negative.
      if (member != &ChamberGas::work && member != &ChamberGas::t && g.*member < 0) {
        in.fail(f + "." + key, "expected >= 0");
      }
    }
    if (!(g.volume > 0)) in.fail(f + ".volume_m3", "expected > 0");
    s.chambers.push_back(g);
  }
}

void read_solver(const Reader& in, const json& j, std::size_t bodies, State& s) {
  const json& m = in.key(j, "solver", "");
  s.solver.t = in.number(in.key(m, "t", "solver"), "solver.t");
  s.solver.dt = in.number(in.key(m, "dt_s", "solver"), "solver.dt_s");
  if (s.solver.dt < 0) in.fail("solver.dt_s", "expected >= 0");
  s.solver.next_output = in.number(in.key(m, "next_output", "solver"), "solver.next_output");
  s.solver.t_start = in.number(in.key(m, "t_start", "solver"), "solver.t_start");
  s.solver.steps = in.integer(in.key(m, "steps", "solver"), "solver.steps");
  if (s.solver.steps < 0) in.fail("solver.steps", "expected >= 0");
  const json& f = in.key(m, "f_W_N", "solver");
  const std::size_t n = f.is_array() && f.empty() ? 0 : bodies;
  s.solver.f_W = in.vecs(f, "solver.f_W_N", n);
  s.solver.tau_W = in.vecs(in.key(m, "tau_W_N_m", "solver"), "solver.tau_W_N_m", n);
  // Generalized-alpha's memory; absent in files written before it was kept.
  if (m.contains("vdot")) {
    const auto numbers = [&](const std::string& k) {
      const json& a = in.key(m, k, "solver");
      if (!a.is_array()) in.fail("solver." + k, "expected an array");
      std::vector<double> out;
      for (const json& x : a) out.push_back(in.number(x, "solver." + k));
      return out;
    };
    s.solver.vdot = numbers("vdot");
    s.solver.accel = numbers("accel");
    if (s.solver.vdot.size() != s.solver.accel.size()) {
      in.fail("solver.accel", "expected as many entries as solver.vdot");
    }
    s.solver.h_prev = in.number(in.key(m, "h_prev_s", "solver"), "solver.h_prev_s");
  }
}

}  // namespace

std::string scene_hash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

nlohmann::json state_json(const Model& model, const StateSnapshot& snap) {
  const State& s = snap.state;
  json bodies = json::array();
  for (std::size_t i = 0; i < s.p_W.size(); ++i) {
    bodies.push_back({{"name", model.bodies[i].name},
                      {"p_W_m", vec_json(s.p_W[i])},
                      {"R_WB", mat_json(s.R_WB[i])},
                      {"v_W_m_s", vec_json(s.v_W[i])},
                      {"w_W_rad_s", vec_json(s.w_W[i])}});
  }
  json elements = json::array();
  for (const ElementHistory& h : s.history) {
    json e = {{"fold_angle_rad", h.fold_angle}, {"openings", h.openings}, {"opened", h.opened}};
    // Zero (absent) for all but joints turned 2 rad or more: 1 MB less at 10^4 segments.
    if (h.rotation_F != Vec3::Zero()) e["rotation_F_rad"] = vec_json(h.rotation_F);
    elements.push_back(std::move(e));
  }
  json j = {{"format", kFormat},
            {"version", kVersion},
            {"scene_hash", snap.scene_hash},
            {"model",
             {{"bodies", model.bodies.size()},
              {"elements", model.elements.size()},
              {"drives", model.drives.size()},
              {"chambers", model.chambers.size()}}},
            {"t", s.t},
            {"load_scale", s.load_scale},
            {"drive_s_m", s.drive_s},
            {"bodies", bodies},
            {"elements", elements},
            {"contact", contact_json(s.contact)},
            {"chambers", chambers_json(model, s)},
            {"solver",
             {{"t", s.solver.t},
              {"dt_s", s.solver.dt},
              {"next_output", s.solver.next_output},
              {"t_start", s.solver.t_start},
              {"steps", s.solver.steps},
              {"f_W_N", vecs_json(s.solver.f_W)},
              {"tau_W_N_m", vecs_json(s.solver.tau_W)},
              {"vdot", s.solver.vdot},
              {"accel", s.solver.accel},
              {"h_prev_s", s.solver.h_prev}}}};
  if (!snap.start_state.empty()) j["start_state"] = snap.start_state;
  return j;
}

StateSnapshot parse_state_json(const nlohmann::json& j, const Model& model,
                               const std::string& file) {
  const Reader in(file);
  if (!j.is_object() || j.value("format", "") != kFormat)
    in.fail("format", fmt::format("expected \"{}\" (not a finseg state file)", kFormat));
  if (in.integer(in.key(j, "version", ""), "version") != kVersion)
    in.fail("version", fmt::format("expected {}", kVersion));
  const json& m = in.key(j, "model", "");
  const std::size_t nb = model.bodies.size(), ne = model.elements.size(), nd = model.drives.size();
  const auto count = [&](const char* name, std::size_t expected) {
    if (in.integer(in.key(m, name, "model"), std::string("model.") + name) !=
        static_cast<long>(expected)) {
      in.fail(std::string("model.") + name,
              fmt::format("the scene's model has {} {}: the state belongs to another model",
                          expected, name));
    }
  };
  count("bodies", nb);
  count("elements", ne);
  count("drives", nd);
  if (!model.chambers.empty() || m.contains("chambers")) count("chambers", model.chambers.size());
  StateSnapshot snap;
  const json& hash = in.key(j, "scene_hash", "");
  if (!hash.is_string()) in.fail("scene_hash", "expected a string");
  snap.scene_hash = hash.get<std::string>();
  if (j.contains("start_state")) {  // optional: absent, the scene's initial state
    if (!j["start_state"].is_string()) in.fail("start_state", "expected a file name");
    snap.start_state = j["start_state"].get<std::string>();
  }
  State& s = snap.state;
  s.t = in.number(in.key(j, "t", ""), "t");
  s.load_scale = in.number(in.key(j, "load_scale", ""), "load_scale");
  const json& drives = in.array(in.key(j, "drive_s_m", ""), "drive_s_m", nd);
  for (std::size_t i = 0; i < nd; ++i)
    s.drive_s.push_back(in.number(drives[i], fmt::format("drive_s_m[{}]", i)));
  read_bodies(in, j, nb, s);
  read_elements(in, j, ne, s);
  read_contact(in, j, nb, s);
  read_solver(in, j, nb, s);
  read_chambers(in, j, model, s);
  return snap;
}

void write_state_file(const std::string& path, const Model& model, const StateSnapshot& snapshot) {
  write_file_atomically(
      path,
      state_json(model, snapshot).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) +
          "\n");
}

StateSnapshot read_state_file(const std::string& path, const Model& model) {
  json j;
  try {
    j = json::parse(read_whole_file(path));
  } catch (const json::exception& e) {
    throw InputError(path, "(file)", std::string("not valid JSON: ") + e.what());
  }
  return parse_state_json(j, model, path);
}

}  // namespace finseg
