// Internal to the scene reader: one function per group of sections (scene_reader.cpp
// calls them in order). Not a public interface.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "model/model.hpp"
#include "scene/scene_reader.hpp"
#include "scene/yaml_fields.hpp"

namespace finseg {

/// Builds the structure from material, sheet, discretisation, stiffness, fixtures, gravity,
/// contact and zigzag or pattern. Sets `zigzag` when the zigzag generator built it and
/// `pattern_file` (the path opened) when a crease pattern did.
Model read_structure(const Fields& root, bool& zigzag, std::string& pattern_file);

/// Appends fixtures by body name, loads, drives and probes (replacing generator probes
/// when `probes:` is given).
void read_attachments(const Fields& root, bool zigzag, Model& model);

/// The `pressures:` section: pressure loads on panels or bodies (docs/scene.md).
void read_pressures(const Fields& root, Model& model);

/// Bodies a section entry selects: `panels: [1, 3]` (1-based) or `bodies: all` or
/// `bodies: [names]` (exactly one of the two keys).
std::vector<int> selected_bodies(const Fields& f, const Model& model);

/// Reads `key: +z | -z`: true for +z; `meaning` explains the choice in the error message.
bool plus_z_side(const Fields& f, const std::string& key, const std::string& meaning);

/// Reads `table: {versus: time | load_scale, at: [..], pressure: [..] Pa}` into `d`.
void read_pressure_table(const Fields& f, PressureDef& d);

/// The `chambers:` section: closed volumes of gas (docs/scene.md, docs/gas.md). Call after
/// the bodies are final; the geometry is checked by prepare_chambers.
void read_chambers(const Fields& root, Model& model);

/// The `solver:` section.
SolverSettings read_solver_section(const Fields& root);

/// The `folding:` section into `scene` (folding, folding_solver); nothing without one.
void read_folding_section(const Fields& root, Scene& scene);

/// The `outputs:` section; defaults depend on the model (drives, panels).
OutputSettings read_outputs_section(const Fields& root, const Model& model);

/// Free memory (MemAvailable of /proc/meminfo) in bytes; nullopt where it cannot be read.
std::optional<double> available_memory_bytes();

/// Refuses a model of `along` x `across` segments that cannot fit in the free memory (or
/// exceeds the 32-bit DOF indexing): InputError(file, fields, "... need at least X GiB ...").
void check_model_memory(double along, double across, const std::string& file,
                        const std::string& fields);

/// Refuses a run whose step or output count exceeds kMaxSteps / kMaxOutputs
/// (solvers/step_limits.hpp); `drive_step_field` names the first drive's step in the scene.
void check_run_size(const Scene& scene, const std::string& drive_step_field);

/// The scene field(s) behind a field of model validation ("bodies[3].mass" ->
/// "material.density, sheet.thickness, ..."): messages name what the user can change.
std::string scene_field_of_model(const std::string& model_field, bool zigzag);

/// Runs `build` and turns an InputError raised by library code against "<api>" into one
/// naming `file` and the scene field (through `scene_field`, identity when empty).
void in_scene_file(const std::string& file, const std::function<void()>& build,
                   const std::function<std::string(const std::string&)>& scene_field = {});

}  // namespace finseg
