#include "vtk_output.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/geometry.hpp"
#include "core/so3.hpp"
#include "formulations/displacement/cell_resultants.hpp"

namespace rotbeam {

namespace {

// The nodes in inertial axes: with a turning frame Q about c (dynamics with turning supports) the
// position c + Q (x^r + u − c) and the rotation Q R of the motion relative to it, as the result's
// `points` (docs/rotating-frame.md); without one the snapshot's own.
struct InertialNodes {
    std::vector<Vec3> position;
    std::vector<Mat3> rotation;  // relative to the reference, R = R^c R^rᵀ
    std::vector<Mat3> frame;     // the section frame R R^r(s) (columns d1, d2, d3)
};

InertialNodes inertial_nodes(const Model& model, const FrameSnapshot& snapshot) {
    std::vector<ReferenceGeometry> geometry;
    for (size_t m = 0; m < model.members.size(); ++m)
        geometry.emplace_back(model, static_cast<int>(m));
    InertialNodes out;
    for (const StaticState::NodeFrame& n : snapshot.nodes) {
        if (snapshot.turning) {
            const Mat3& Q = snapshot.turning->rotation;
            const Vec3& c = snapshot.turning->center;
            out.position.push_back(c + Q * (n.reference + n.displacement - c));
            out.rotation.push_back(Q * n.rotation);
        } else {
            out.position.push_back(n.reference + n.displacement);
            out.rotation.push_back(n.rotation);
        }
        out.frame.push_back(out.rotation.back() *
                            geometry[static_cast<size_t>(n.member)].frame(n.s));
    }
    return out;
}

// Every double with 17 significant digits, so that it reads back exactly.
class DataArrayWriter {
  public:
    explicit DataArrayWriter(std::ostringstream& os) : os_(os) {}

    // A Float64 array of `count` tuples of `components`, value(i, c).
    void floats(const std::string& name, size_t count, int components,
                const std::function<double(size_t, int)>& value) {
        os_ << "        <DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\""
            << components << "\" format=\"ascii\">\n         ";
        for (size_t i = 0; i < count; ++i) {
            for (int c = 0; c < components; ++c) os_ << " " << number(value(i, c));
        }
        os_ << "\n        </DataArray>\n";
    }
    void vectors(const std::string& name, const std::vector<Vec3>& v) {
        floats(name, v.size(), 3, [&](size_t i, int c) { return v[i][c]; });
    }
    void integers(const std::string& type, const std::string& name, const std::vector<long>& v) {
        os_ << "        <DataArray type=\"" << type << "\" Name=\"" << name
            << "\" format=\"ascii\">\n         ";
        for (long x : v) os_ << " " << x;
        os_ << "\n        </DataArray>\n";
    }

  private:
    static std::string number(double x) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", x);
        return buffer;
    }
    std::ostringstream& os_;
};

// Field data of the step's (or mode's) error estimate, where the run has one.
void estimate_field_data(const nlohmann::json& result, size_t index, DataArrayWriter& w) {
    auto write = [&](const std::string& name, const nlohmann::json& q) {
        if (!q.is_object() || !q.contains("error")) return;
        const double error = q["error"].get<double>();
        const double reliable = q.value("reliable", false) ? 1.0 : 0.0;
        w.floats(name, 1, 1, [&](size_t, int) { return error; });
        w.floats(name + "_reliable", 1, 1, [&](size_t, int) { return reliable; });
    };
    if (result.contains("modes")) {
        const nlohmann::json& mode = result["modes"][index];
        if (mode.contains("estimate"))
            write("estimate_frequency_hz", mode["estimate"].value("frequency", nlohmann::json()));
        return;
    }
    const nlohmann::json& step = result["steps"][index];
    if (!step.contains("estimate")) return;
    const nlohmann::json& e = step["estimate"];
    for (const auto& [name, point] : step["points"].items()) {
        const nlohmann::json& p = e.contains(name) ? e[name] : e;
        write("estimate_" + name + "_displacement", p.value("displacement", nlohmann::json()));
        write("estimate_" + name + "_rotation", p.value("rotation", nlohmann::json()));
    }
}

// Point data of the step's error estimate: the estimated error of the displacement and of the
// rotation at each named point the step has one for, at the node at that point (and the ribbon's
// points beside it), with its `reliable` as 1 or 0; every other point has −1, "no estimate" (the
// program estimates the error of the named points' quantities only). A static step's estimate
// and a dynamic run's at each output time (space + time); not a mode's, which is of its frequency
// (field data).
void estimate_point_data(const Model& model, const nlohmann::json& result, size_t index,
                         const std::vector<StaticState::NodeFrame>& nodes, DataArrayWriter& w) {
    if (result.contains("modes")) return;
    const nlohmann::json& step = result["steps"][index];
    if (!step.contains("estimate")) return;
    const nlohmann::json& e = step["estimate"];
    std::vector<double> scale{1.0};  // the structure's size, for the position match
    for (const Point& p : model.points) scale.push_back(p.position.cwiseAbs().maxCoeff());
    const double slack = 1e-12 * *std::max_element(scale.begin(), scale.end());
    const size_t n = nodes.size();
    for (const char* quantity : {"displacement", "rotation"}) {
        std::vector<double> error(n, -1.0), reliable(n, -1.0);
        for (const Point& p : model.points) {
            if (!step["points"].contains(p.name)) continue;
            const nlohmann::json& q =
                (e.contains(p.name) ? e[p.name] : e).value(quantity, nlohmann::json());
            if (!q.is_object() || !q.contains("error")) continue;
            for (size_t i = 0; i < n; ++i) {
                if ((nodes[i].reference - p.position).norm() > slack) continue;
                error[i] = q["error"].get<double>();
                reliable[i] = q.value("reliable", false) ? 1.0 : 0.0;
            }
        }
        const std::string name = std::string("estimate_") + quantity;
        w.floats(name, 3 * n, 1, [&](size_t i, int) { return error[i % n]; });
        w.floats(name + "_reliable", 3 * n, 1, [&](size_t i, int) { return reliable[i % n]; });
    }
}

// Whether `r` holds one resultant per line cell, in their order: on the cell's member, between
// its nodes.
bool resultants_fit_cells(const std::vector<SectionResultants>& r,
                          const std::vector<StaticState::NodeFrame>& nodes,
                          const std::vector<size_t>& segments) {
    if (segments.empty() || r.size() != segments.size()) return false;
    for (size_t c = 0; c < segments.size(); ++c) {
        const StaticState::NodeFrame& a = nodes[segments[c]];
        const StaticState::NodeFrame& b = nodes[segments[c] + 1];
        if (r[c].member != a.member || !(r[c].s > a.s && r[c].s < b.s)) return false;
    }
    return true;
}

// The step's load factor or time, or the mode's number (from 1).
double time_value(const nlohmann::json& result, size_t index) {
    if (result.contains("modes")) return static_cast<double>(index + 1);
    const nlohmann::json& step = result["steps"][index];
    return step.contains("time") ? step["time"].get<double>() : step["load_factor"].get<double>();
}

double ribbon_half_width(const Model& model) {
    double longest = 0.0;
    for (size_t m = 0; m < model.members.size(); ++m) {
        longest = std::max(longest, ReferenceGeometry(model, static_cast<int>(m)).length());
    }
    return longest / 40.0;
}

}  // namespace

std::string vtk_unstructured_grid(const Model& model, const nlohmann::json& result, size_t index,
                                  const FrameSnapshot& snapshot) {
    const std::vector<StaticState::NodeFrame>& nodes = snapshot.nodes;
    const size_t n = nodes.size();
    const InertialNodes inertial = inertial_nodes(model, snapshot);
    const std::vector<Mat3>& frames = inertial.frame;
    const double half_width = ribbon_half_width(model);
    // Points: the nodes, then the ribbon's edges x ∓ h d2.
    std::vector<Vec3> points(3 * n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3& x = inertial.position[i];
        points[i] = x;
        points[n + i] = x - half_width * frames[i].col(1);
        points[2 * n + i] = x + half_width * frames[i].col(1);
    }
    // Cells: a line per pair of neighbouring nodes of a member, then the ribbon's quad over it.
    std::vector<size_t> segments;  // the first node of each pair
    for (size_t i = 0; i + 1 < n; ++i) {
        if (nodes[i].member == nodes[i + 1].member) segments.push_back(i);
    }
    std::vector<long> connectivity, offsets, types, cell_member;
    for (size_t i : segments) {
        connectivity.insert(connectivity.end(), {long(i), long(i + 1)});
        offsets.push_back(static_cast<long>(connectivity.size()));
        types.push_back(3);  // VTK_LINE
        cell_member.push_back(nodes[i].member);
    }
    for (size_t i : segments) {
        connectivity.insert(connectivity.end(),
                            {long(n + i), long(n + i + 1), long(2 * n + i + 1), long(2 * n + i)});
        offsets.push_back(static_cast<long>(connectivity.size()));
        types.push_back(9);  // VTK_QUAD
        cell_member.push_back(nodes[i].member);
    }
    const size_t cells = types.size();

    std::ostringstream os;
    DataArrayWriter w(os);
    os << "<?xml version=\"1.0\"?>\n"
          "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
          "header_type=\"UInt64\">\n  <UnstructuredGrid>\n      <FieldData>\n";
    const double t = time_value(result, index);
    w.floats("TimeValue", 1, 1, [&](size_t, int) { return t; });
    if (snapshot.turning) {
        const Vec3 q = so3::log_map(snapshot.turning->rotation);
        w.floats("frame_rotation_vector", 1, 3, [&](size_t, int c) { return q[c]; });
    }
    estimate_field_data(result, index, w);
    os << "      </FieldData>\n    <Piece NumberOfPoints=\"" << points.size()
       << "\" NumberOfCells=\"" << cells << "\">\n      <PointData>\n";
    // Point data: the ribbon's points (index ≥ n) carry their node's values.
    const auto node_of = [n](size_t p) { return p % n; };
    const auto per_point = [&](const std::string& name, const std::function<Vec3(size_t)>& f) {
        w.floats(name, points.size(), 3, [&](size_t p, int c) { return f(node_of(p))[c]; });
    };
    // Inertial, like the result's `points`: with a turning frame the position less the reference.
    per_point("displacement", [&](size_t i) {
        return snapshot.turning ? Vec3(points[i] - nodes[i].reference) : nodes[i].displacement;
    });
    per_point("rotation_vector", [&](size_t i) { return so3::log_map(inertial.rotation[i]); });
    if (snapshot.turning) {
        per_point("relative_displacement", [&](size_t i) { return nodes[i].displacement; });
        per_point("relative_rotation_vector",
                  [&](size_t i) { return so3::log_map(nodes[i].rotation); });
    }
    for (int d = 0; d < 3; ++d) {
        per_point("director_" + std::to_string(d + 1),
                  [&](size_t i) { return Vec3(frames[i].col(d)); });
    }
    per_point("reference_position", [&](size_t i) { return nodes[i].reference; });
    w.floats("arc_length", points.size(), 1, [&](size_t p, int) { return nodes[node_of(p)].s; });
    w.floats("member", points.size(), 1,
             [&](size_t p, int) { return static_cast<double>(nodes[node_of(p)].member); });
    if (snapshot.mode.size() == n) {
        per_point("mode_displacement", [&](size_t i) { return Vec3(snapshot.mode[i].head<3>()); });
        per_point("mode_rotation", [&](size_t i) { return Vec3(snapshot.mode[i].tail<3>()); });
    }
    estimate_point_data(model, result, index, nodes, w);
    os << "      </PointData>\n      <CellData>\n";
    w.floats("member", cells, 1,
             [&](size_t c, int) { return static_cast<double>(cell_member[c]); });
    // The section resultants, one per line cell: the mixed formulation's (its element
    // mid-points), or the displacement formulation's evaluated midway between the nodes.
    const std::vector<SectionResultants> r =
        snapshot.field ? form::displacement_cell_resultants(model, *snapshot.field)
                       : snapshot.sections;
    if (resultants_fit_cells(r, nodes, segments)) {
        const size_t k = segments.size();
        // Inertial components turned from a turning frame's axes; the material ones as they are.
        const Mat3 Q = snapshot.turning ? snapshot.turning->rotation : Mat3::Identity();
        const auto per_cell = [&](const std::string& name, Vec3 SectionResultants::*field,
                                  bool inertial_axes) {
            w.floats(name, cells, 3, [&](size_t c, int i) {
                const Vec3& v = r[c % k].*field;
                return inertial_axes && snapshot.turning ? Vec3(Q * v)[i] : v[i];
            });
        };
        per_cell("section_force", &SectionResultants::force, true);
        per_cell("section_moment", &SectionResultants::moment, true);
        per_cell("section_force_material", &SectionResultants::force_material, false);
        per_cell("section_moment_material", &SectionResultants::moment_material, false);
    }
    os << "      </CellData>\n      <Points>\n";
    w.vectors("position", points);
    os << "      </Points>\n      <Cells>\n";
    w.integers("Int64", "connectivity", connectivity);
    w.integers("Int64", "offsets", offsets);
    w.integers("UInt8", "types", types);
    os << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return os.str();
}

std::string write_vtk(const std::string& directory, const Model& model,
                      const nlohmann::json& result, const std::vector<FrameSnapshot>& snapshots) {
    namespace fs = std::filesystem;
    const std::string base = result["case"].get<std::string>() + "_" +
                             result["rotation"].get<std::string>() + "_" +
                             result["formulation"].get<std::string>();
    std::ostringstream pvd;
    pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
           "  <Collection>\n";
    for (size_t i = 0; i < snapshots.size(); ++i) {
        char number[32];
        std::snprintf(number, sizeof number, "_%04zu.vtu", i);
        const std::string file = base + number;
        write_file_atomically((fs::path(directory) / file).string(),
                              vtk_unstructured_grid(model, result, i, snapshots[i]));
        char t[32];
        std::snprintf(t, sizeof t, "%.17g", time_value(result, i));
        pvd << "    <DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
    }
    pvd << "  </Collection>\n</VTKFile>\n";
    const std::string path = (fs::path(directory) / (base + ".pvd")).string();
    write_file_atomically(path, pvd.str());
    return path;
}

}  // namespace rotbeam
