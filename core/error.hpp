#pragma once
/// The error type for bad input and for what a backend cannot do.

#include <cstdio>
#include <stdexcept>
#include <string>

namespace cairn {

/// Bad input or an unsupported request; what() is the full message shown to the user.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// a number for a message, printf "%.<digits>g" (1e+30, 0.0111)
inline std::string message_number(double x, int digits = 4) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

}  // namespace cairn
