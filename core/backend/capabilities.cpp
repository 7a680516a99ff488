#include "backend/capabilities.hpp"

namespace cairn {

const char* to_string(Support s) {
    switch (s) {
        case Support::exact: return "exact";
        case Support::approximate: return "approximate";
        case Support::none: return "none";
    }
    return "?";
}

}  // namespace cairn
