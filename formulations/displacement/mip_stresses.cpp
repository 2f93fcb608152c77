#include "formulations/displacement/mip_stresses.hpp"

#include "core/errors.hpp"

namespace rotbeam::form {

void MipStresses::setup(const Mesh& mesh, bool enabled) {
    enabled_ = enabled;
    if (!enabled_) return;
    nn_ = static_cast<size_t>(mesh.order) + 1;
    first_point_.clear();
    size_t points = 0;
    for (const MeshElement& e : mesh.elements) {
        first_point_.push_back(static_cast<int>(points));
        points += e.qp.size();
    }
    sigma_.assign(points, Vec6::Zero());
    Q_.assign(points, Mat3::Identity());
    F_.assign(points, Vec6::Zero());
    S_.assign(points * nn_, Mat6::Zero());
    for (auto& s : saved_sigma_) s = sigma_;
}

Vec6 MipStresses::geometric_force(int g, const Mat3& Q, const Vec6& FE1) const {
    if (!known_) return FE1;
    const Vec6& s = sigma_[static_cast<size_t>(g)];
    Vec6 f;
    f.head<3>() = Q * s.head<3>();
    f.tail<3>() = Q * s.tail<3>();
    return f;
}

void MipStresses::retract(const Mesh& mesh, const Eigen::Ref<const VecX>& dx) {
    if (!enabled_) return;
    known_ = maps_id_ == state_id_;
    state_id_ = next_id_++;
    if (!known_) return;
    for (size_t k = 0; k < mesh.elements.size(); ++k) {
        const MeshElement& e = mesh.elements[k];
        for (size_t q = 0; q < e.qp.size(); ++q) {
            const size_t g = static_cast<size_t>(first_point_[k]) + q;
            Vec6 f = F_[g];
            for (size_t b = 0; b < e.nodes.size(); ++b) {
                const int d = mesh.nodes[static_cast<size_t>(e.nodes[b])].dof;
                if (d >= 0) f.noalias() += S_[g * nn_ + b] * dx.segment<6>(d);
            }
            sigma_[g].head<3>() = Q_[g].transpose() * f.head<3>();
            sigma_[g].tail<3>() = Q_[g].transpose() * f.tail<3>();
        }
    }
}

void MipStresses::drop() {
    known_ = false;
    state_id_ = next_id_++;
}

void MipStresses::save(int slot) {
    if (!enabled_) return;
    ROTBEAM_VERIFY(slot >= 0 && slot < NonlinearSystem::kCheckpointSlots,
                   "checkpoint slot out of range");
    saved_sigma_[static_cast<size_t>(slot)] = sigma_;
    saved_known_[static_cast<size_t>(slot)] = known_;
    saved_id_[static_cast<size_t>(slot)] = state_id_;
}

void MipStresses::restore(int slot) {
    if (!enabled_) return;
    ROTBEAM_VERIFY(slot >= 0 && slot < NonlinearSystem::kCheckpointSlots,
                   "checkpoint slot out of range");
    sigma_ = saved_sigma_[static_cast<size_t>(slot)];
    known_ = saved_known_[static_cast<size_t>(slot)];
    state_id_ = saved_id_[static_cast<size_t>(slot)];
}

}  // namespace rotbeam::form
