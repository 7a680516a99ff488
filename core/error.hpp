#pragma once
/// The error type for bad input and for what a backend cannot do.

#include <cstdio>
#include <stdexcept>
#include <string>

#include "output/number_format.hpp"   // message_number, the numbers of messages

namespace cairn {

/// Bad input or an unsupported request; what() is the full message shown to the user.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace cairn
