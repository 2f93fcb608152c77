// Internal to the case loader: the readers of each top-level section of a case file. Each one
// validates what it reads and fills its part of the Model; cross-references (a load's point, a
// member's section) are checked against what was read before, so the order of calls matters:
// points, sections, members, constraints, loads, analysis, discretization, solver, references.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "cases/loader/yaml_reader.hpp"
#include "core/model.hpp"

namespace rotbeam::cases {

using SectionTable = std::map<std::string, Section>;

void read_points(const YamlReader& r, const YAML::Node& root, Model& model);
// The names of the model's points, in order: the valid values of a key that names a point.
std::vector<std::string> point_names(const Model& model);
SectionTable read_sections(const YamlReader& r, const YAML::Node& root);
void read_members(const YamlReader& r, const YAML::Node& root, const SectionTable& sections,
                  Model& model);
// Geometry that double arithmetic resolves (geometry_checks.cpp, docs/case-format.md): the
// problem with a member of `length` whose elements are too short to compute with, else empty;
// the distance between its end points (a straight member's length, computed without underflow).
std::string element_length_problem(const Model& model, const Member& member, double length);
double chord_length(const Model& model, const Member& member);
// No two points closer than such an element: one place has one name.
void check_distinct_points(const YamlReader& r, const YAML::Node& root, const Model& model);
void read_constraints(const YamlReader& r, const YAML::Node& root, Model& model);
void read_loads(const YamlReader& r, const YAML::Node& root, Model& model);
TimeFunction read_time_function(const YamlReader& r, const YAML::Node& node,
                                const std::string& key);

void read_analysis(const YamlReader& r, const YAML::Node& root, Model& model);
void read_discretization(const YamlReader& r, const YAML::Node& root, Model& model);
void read_solver(const YamlReader& r, const YAML::Node& root, Model& model);
// `references` and `expected_stops` (references.cpp).
void read_references(const YamlReader& r, const YAML::Node& root, Model& model);

// Values shared by discretization and references.applies_to (the enum choices: choice_names).
extern const std::vector<std::string> kQuadratures;

// The enum E named by `node` (one of choice_names<E>(), else fails naming the key and the choices):
// where a case's names become enums (core/choices.hpp).
template <class E>
E read_choice(const YamlReader& r, const YAML::Node& node, const std::string& key) {
    return *parse_choice<E>(r.choice(node, key, choice_names<E>()));
}

// The parameterization named by `node` (one of the registry's names).
ParameterizationId read_rotation(const YamlReader& r, const YAML::Node& node,
                                 const std::string& key);

}  // namespace rotbeam::cases
