// Fixtures by body name, loads, drives and probes of a scene file (docs/scene.md).
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "core/text.hpp"
#include "generators/sheet.hpp"
#include "scene/scene_parts.hpp"

namespace finseg {
namespace {

std::string body_names_hint(const Model& m) {
  if (m.bodies.empty()) return "the model has no body";
  return fmt::format("bodies are {} .. {} ({} in all; finseg inspect lists them)",
                     m.bodies.front().name, m.bodies.back().name, m.bodies.size());
}

int body_by_name(const Model& m, const std::string& name, const YamlContext& ctx) {
  const int b = m.body_index(name);
  if (b < 0) {
    throw InputError(
        ctx.file, ctx.field,
        fmt::format("{} is not a body of the model; {}", quoted(name), body_names_hint(m)));
  }
  return b;
}

// Where a load, drive or point probe attaches: `at: {s, y}` (material point on the flat
// sheet, m) or `body: NAME` with `point: [x, y, z]` in that body's frame (m).
MaterialPoint read_location(const Fields& f, const Model& m) {
  if (f.has("at")) {
    if (f.has("body") || f.has("point")) f.fail("at", "give either at: {s, y} or body (+ point)");
    const Fields at(f.node("at"), f.context("at"), {"s", "y"});
    const Vec2& o = m.sheet.origin_M;
    const double s = at.number("s", interval(o.x(), o.x() + m.sheet.length, false, false, "m"));
    const double y = at.number("y", interval(o.y(), o.y() + m.sheet.width, false, false, "m"));
    MaterialPoint p;
    in_scene_file(
        f.context().file, [&] { p = locate_material_point(m, s, y); },
        [&](const std::string&) { return f.field("at"); });
    return p;
  }
  if (!f.has("body")) f.fail("at", "required: at: {s, y} (m) or body: NAME");
  MaterialPoint p;
  p.body = body_by_name(m, f.word("body", ""), f.context("body"));
  p.r_B = f.vector3("point", Vec3::Zero(), "m, body frame");
  return p;
}

void read_fixed_bodies(const Fields& root, Model& m) {
  const Fields fix(root.node("fixtures"), root.context("fixtures"),
                   {"clamp_start", "panels", "bodies"});
  const std::vector<std::string> names = fix.words("bodies");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const YamlContext ctx{fix.context().file, item_field(fix.field("bodies"), i)};
    m.bodies[body_by_name(m, names[i], ctx)].fixed = true;
  }
}

void read_loads(const Fields& root, Model& m) {
  const auto items = sequence(root.node("loads"), root.context("loads"), "loads");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields f(items[i], {root.context().file, item_field("loads", i)},
                   {"name", "at", "body", "point", "force", "moment", "follower"});
    const MaterialPoint p = read_location(f, m);
    LoadDef l;
    l.body = p.body;
    l.point_B = p.r_B;
    l.force = f.vector3("force", Vec3::Zero(), "N");
    l.moment = f.vector3("moment", Vec3::Zero(), "N m");
    l.follower = f.flag("follower", false);
    m.loads.push_back(l);
  }
}

void read_drives(const Fields& root, bool zigzag, Model& m) {
  const auto items = sequence(root.node("drives"), root.context("drives"), "drives");
  if (zigzag && !items.empty()) {
    root.fail("drives", "a zigzag scene has one drive, 'gauge', set by the zigzag: pull_* keys");
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields f(items[i], {root.context().file, item_field("drives", i)},
                   {"name", "at", "body", "point", "direction", "stiffness", "lateral_stiffness",
                    "pull_only", "toe_force", "damping", "speed", "travel", "step", "deployed_at"});
    DriveDef d;
    d.name = f.required_word("name");
    for (const DriveDef& other : m.drives) {
      if (other.name == d.name)
        f.fail("name", quoted(d.name) + " is used twice; names must differ");
    }
    const MaterialPoint p = read_location(f, m);
    d.body = p.body;
    d.point_B = p.r_B;
    d.start_W = m.bodies[p.body].p0_W + m.bodies[p.body].R0_WB * p.r_B;
    const Vec3 dir = f.vector3("direction", Vec3::UnitZ(), "unit vector");
    if (!(dir.norm() > 0)) f.fail("direction", "must be a non-zero vector");
    d.direction_W = dir / dir.norm();
    d.stiffness = f.number("stiffness", positive("N/m"));
    d.lateral_ratio = f.number("lateral_stiffness", d.stiffness, non_negative("N/m")) / d.stiffness;
    d.pull_only = f.flag("pull_only", false);
    d.toe_force = f.number("toe_force", 0.0, non_negative("N"));
    d.damping = f.number("damping", 0.0, non_negative("N s/m"));
    d.travel = f.number("travel", 0.0, non_negative("m"));
    d.step = f.number("step", 0.0, non_negative("m"));
    d.speed = f.number("speed", d.travel, non_negative("m/s"));
    d.deployed_at = f.number("deployed_at", 0.0, non_negative("m (0: the whole travel)"));
    if (d.travel > 0 && !(d.step > 0) && i == 0) {
      f.fail("step", "required (> 0 m) with travel > 0: the static solver's pull increment");
    }
    m.drives.push_back(d);
  }
}

ProbeKind probe_kind(const Fields& f) {
  static const std::map<std::string, ProbeKind> kinds{
      {"point", ProbeKind::Point},       {"drive", ProbeKind::Drive},
      {"reaction", ProbeKind::Reaction}, {"energy", ProbeKind::Energy},
      {"contact", ProbeKind::Contact},   {"crease", ProbeKind::Crease},
      {"element", ProbeKind::Element},   {"pose", ProbeKind::Pose},
      {"shape", ProbeKind::Shape},       {"unfolding", ProbeKind::Unfolding}};
  const std::string type = f.required_word("type");
  const auto it = kinds.find(type);
  if (it == kinds.end()) {
    f.fail("type", quoted(type) +
                       "; allowed: point, drive, reaction, energy, contact, crease, element, "
                       "pose, shape, unfolding");
  }
  return it->second;
}

// Names of the files a probe's table goes to (without ".csv").
std::vector<std::string> file_stems(const ProbeDef& p) {
  if (p.pairs) return {p.name, p.name + "_pairs"};
  if (p.kind == ProbeKind::Unfolding) return {p.name, p.name + "_order"};
  return {p.name};
}

// Two probes must not write the same file: equal names, or a name equal to another
// contact probe's pairs file.
void check_file_names(const Fields& f, const ProbeDef& p, const std::vector<ProbeDef>& earlier) {
  for (const ProbeDef& other : earlier) {
    if (other.name == p.name) f.fail("name", quoted(p.name) + " is used twice; names must differ");
    for (const std::string& a : file_stems(p)) {
      for (const std::string& b : file_stems(other)) {
        if (a == b)
          f.fail("name",
                 quoted(p.name) + " and " + quoted(other.name) + " both write " + a + ".csv");
      }
    }
  }
}

// The model's shape named by field `shape`.
int shape_index(const Fields& f, const Model& m) {
  const std::string name = f.required_word("shape");
  std::string known;
  for (std::size_t k = 0; k < m.shapes.size(); ++k) {
    if (m.shapes[k].name == name) return static_cast<int>(k);
    known += (k ? ", " : "") + quoted(m.shapes[k].name);
  }
  f.fail("shape", quoted(name) + " is not a shape of the model (" +
                      (known.empty() ? std::string("it has none: a pattern's further "
                                                   "foldedForm frames are its shapes")
                                     : "its shapes: " + known) +
                      ")");
}

// Crease, element, pose, shape and unfolding probes: which crease (1-based), element, body
// or shape they watch.
void read_target(const Fields& f, const Model& m, ProbeDef& p) {
  if (p.kind == ProbeKind::Crease) {
    if (m.creases.empty()) f.fail("type", "crease probe, but the model has no crease");
    p.crease = f.integer("crease", -1, 1, static_cast<int>(m.creases.size())) - 1;
    if (p.crease < 0) f.fail("crease", fmt::format("required: 1 .. {}", m.creases.size()));
  } else if (p.kind == ProbeKind::Element) {
    const std::string name = f.required_word("element");
    for (std::size_t k = 0; k < m.elements.size(); ++k) {
      if (m.elements[k].name == name) p.element = static_cast<int>(k);
    }
    if (p.element < 0) {
      f.fail("element",
             "'" + name + "' is not a force element (finseg inspect --incidence lists them)");
    }
  } else if (p.kind == ProbeKind::Pose) {
    p.body = body_by_name(m, f.required_word("body"), f.context("body"));
  } else if (p.kind == ProbeKind::Shape) {
    p.shape = shape_index(f, m);
  } else if (p.kind == ProbeKind::Unfolding) {
    if (m.creases.empty()) f.fail("type", "unfolding probe, but the model has no crease");
    if (f.has("shape")) p.shape = shape_index(f, m);  // else the creases open to flat
  }
}

// A drive probe's drives: `drive: name`, or `drives: [names]` whose gauges move alike (the same
// speed and travel: one pull displacement) and are summed.
std::vector<int> probed_drives(const Fields& f, const Model& m) {
  if (f.has("drive") == f.has("drives")) {
    f.fail(f.has("drive") ? "drives" : "drive", "give either drive: <name> or drives: [<names>]");
  }
  const std::string key = f.has("drive") ? "drive" : "drives";
  const std::vector<std::string> names =
      key == "drive" ? std::vector<std::string>{f.required_word("drive")} : f.words("drives");
  if (names.empty()) f.fail(key, "names no drive");
  std::vector<int> drives;
  for (const std::string& name : names) {
    int found = -1;
    for (std::size_t d = 0; d < m.drives.size(); ++d) {
      if (m.drives[d].name == name) found = static_cast<int>(d);
    }
    if (found < 0) f.fail(key, quoted(name) + " is not a drive of the scene");
    if (std::find(drives.begin(), drives.end(), found) != drives.end()) {
      f.fail(key, quoted(name) + " is named twice");
    }
    const DriveDef &d = m.drives[found], &first = m.drives[drives.empty() ? found : drives[0]];
    if (d.speed != first.speed || d.travel != first.travel) {
      f.fail(key, fmt::format("{} moves {} m at {} m/s, {} {} m at {} m/s; the drives of one "
                              "probe must move alike (the same speed and travel)",
                              quoted(name), d.travel, d.speed, quoted(first.name), first.travel,
                              first.speed));
    }
    drives.push_back(found);
  }
  return drives;
}

void read_probes(const Fields& root, Model& m) {
  if (!root.has("probes")) return;  // keep the generator's probes
  m.probes.clear();
  const auto items = sequence(root.node("probes"), root.context("probes"), "probes");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Fields f(items[i], {root.context().file, item_field("probes", i)},
                   {"name", "type", "at", "body", "point", "drive", "drives", "pairs", "crease",
                    "element", "shape"});
    ProbeDef p;
    p.name = f.required_word("name");
    if (p.name.empty() || p.name.find_first_of("/\\ ") != std::string::npos || p.name[0] == '.') {
      f.fail("name",
             quoted(p.name) + "; must be a non-empty file-name-safe word (no / \\ or space)");
    }
    p.kind = probe_kind(f);
    p.pairs = f.flag("pairs", false);
    if (f.has("pairs") && p.kind != ProbeKind::Contact) f.fail("pairs", "only for type: contact");
    if (f.has("crease") && p.kind != ProbeKind::Crease) f.fail("crease", "only for type: crease");
    if (f.has("element") && p.kind != ProbeKind::Element) {
      f.fail("element", "only for type: element");
    }
    if (f.has("shape") && p.kind != ProbeKind::Shape && p.kind != ProbeKind::Unfolding) {
      f.fail("shape", "only for type: shape or unfolding");
    }
    check_file_names(f, p, m.probes);
    if (p.kind == ProbeKind::Point) {
      const MaterialPoint at = read_location(f, m);
      p.body = at.body;
      p.point_B = at.r_B;
    } else if (p.kind == ProbeKind::Drive) {
      p.drives = probed_drives(f, m);
    } else {
      read_target(f, m, p);
    }
    m.probes.push_back(p);
  }
}

}  // namespace

void read_attachments(const Fields& root, bool zigzag, Model& m) {
  read_fixed_bodies(root, m);
  m.finalize_dofs();
  read_loads(root, m);
  read_drives(root, zigzag, m);
  read_probes(root, m);
}

}  // namespace finseg
