// The models of tests/displacement/models.hpp that need no case file, compiled once for every test
// that includes the header (the 6×6 inverse of full_section alone instantiates Eigen's LU in each
// file otherwise).
#include "tests/displacement/models.hpp"

namespace rotbeam::test {

Section diagonal_section(double EA, double GA2, double GA3, double GJ, double EI2, double EI3) {
    Section s;
    Vec6 d;
    d << EA, GA2, GA3, GJ, EI2, EI3;
    s.stiffness = Mat6(d.asDiagonal());
    s.compliance = Mat6(d.cwiseInverse().asDiagonal());
    return s;
}

Section full_section(const Mat6& C) {
    Section s;
    s.stiffness = C;
    s.compliance = C.inverse();
    return s;
}

Model cantilever(const Vec3& tip, const Section& section, int elements, int order) {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", tip}};
    Member mem;
    mem.name = "beam";
    mem.start_point = 0;
    mem.end_point = 1;
    mem.sections = {{0.0, section}};
    mem.elements = elements;
    m.members = {mem};
    Constraint c;
    c.point = 0;
    m.constraints = {c};
    m.discretization.order = order;
    return m;
}

}  // namespace rotbeam::test
