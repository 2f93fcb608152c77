// The message of the InputError a call throws, for tests of the loader's refusals.
#pragma once

#include <string>

#include "core/errors.hpp"

namespace rotbeam::test {

// The message of the InputError thrown by `f` (empty when none is thrown).
template <class F>
std::string input_error(F f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace rotbeam::test
