#pragma once
/// The error type for bad input and for what a backend cannot do.

#include <stdexcept>
#include <string>

namespace cairn {

/// Bad input or an unsupported request; what() is the full message shown to the user.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace cairn
