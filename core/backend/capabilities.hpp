#pragma once
/// What a backend can represent of a scene: exactly, approximately (and how), or not at all.

#include <string>
#include <vector>

namespace cairn {

enum class Support { exact, approximate, none };

/// One scene feature and how a backend represents it.
struct FeatureSupport {
    std::string feature;   ///< e.g. "elastic stick before slip"
    Support support = Support::none;
    std::string how;       ///< for approximate/none: what is done instead
};

const char* to_string(Support s);

}  // namespace cairn
