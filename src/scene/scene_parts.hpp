// Internal to the scene reader: one function per group of sections (scene_reader.cpp
// calls them in order). Not a public interface.
#pragma once

#include <functional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "model/model.hpp"
#include "scene/scene_reader.hpp"
#include "scene/yaml_fields.hpp"

namespace finseg {

/// Builds the structure from material, sheet, discretisation, stiffness, fixtures, gravity,
/// contact and zigzag. Sets `zigzag` when the zigzag generator built it.
Model read_structure(const Fields& root, bool& zigzag);

/// Appends fixtures by body name, loads, drives and probes (replacing generator probes
/// when `probes:` is given).
void read_attachments(const Fields& root, bool zigzag, Model& model);

/// The `pressures:` section: pressure loads on panels or bodies (docs/scene.md).
void read_pressures(const Fields& root, Model& model);

/// The `solver:` section.
SolverSettings read_solver_section(const Fields& root);

/// The `outputs:` section; defaults depend on the model (drives, panels).
OutputSettings read_outputs_section(const Fields& root, const Model& model);

/// Runs `build` and turns an InputError raised by library code against "<api>" into one
/// naming `file` and the scene field (through `scene_field`, identity when empty).
void in_scene_file(const std::string& file, const std::function<void()>& build,
                   const std::function<std::string(const std::string&)>& scene_field = {});

}  // namespace finseg
