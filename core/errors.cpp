#include "core/errors.hpp"

namespace rotbeam {

void verify_failed(const char* condition, const std::string& message, const char* file,
                   int line) {
    std::ostringstream s;
    s << file << ":" << line << ": verify(" << condition << ") failed: " << message;
    throw std::logic_error(s.str());
}

}  // namespace rotbeam
