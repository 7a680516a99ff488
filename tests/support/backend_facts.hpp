#pragma once
// Backend facts for compare tests that must not link the engines: a penalty engine with deformable
// blocks (like dem), a rigid-contact engine with a matched spring mode (like Bullet) and one
// without (like Siconos).

#include "backend/backend_info.hpp"

namespace cairn::test {

inline BackendInfo penalty_engine(const std::string& name) {
    BackendInfo b;
    b.name = name;
    b.contact = ContactModel::penalty;
    b.capabilities = {{Feature::penalty_stiffness, Support::exact, ""}, {Feature::deformable_blocks, Support::exact, ""}};
    return b;
}

inline BackendInfo rigid_engine(const std::string& name, bool matched_springs = true) {
    BackendInfo b;
    b.name = name;
    b.contact = ContactModel::rigid;
    b.capabilities = {{Feature::penalty_stiffness, matched_springs ? Support::approximate : Support::none, ""}};
    return b;
}

}  // namespace cairn::test
