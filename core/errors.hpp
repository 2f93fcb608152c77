// Error types of rotbeam and the always-on `verify`.
//
// - InputError: the user's input is wrong (case file, command line). The program prints its
//   one-line message and exits with code 2.
// - SingularityError: a parameterization was asked for something at or beyond its singular set
//   (or with non-finite input). Solvers turn it into the status `singular`.
// - SolverError: a numerical procedure failed (factorization, integrator setup). Solvers turn it
//   into `diverged`/`error`.
// - OutputError: an output file could not be written (full disk, file size limit, permissions).
//   The message names the file; nothing partial is left (core/atomic_file.hpp). Exit code 4.
// `ROTBEAM_VERIFY(cond, msg)` is always on and throws std::logic_error with file:line: it guards
// API misuse, not user input (user input gets an InputError with file/key context).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace rotbeam {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class SingularityError : public std::runtime_error {
public:
    SingularityError(const std::string& parameterization, const std::string& function,
                     double angle, const std::string& detail = "")
        : std::runtime_error(format(parameterization, function, angle, detail)),
          parameterization_(parameterization),
          function_(function),
          angle_(angle) {}

    const std::string& parameterization() const { return parameterization_; }
    const std::string& function() const { return function_; }
    double angle() const { return angle_; }

private:
    static std::string format(const std::string& p, const std::string& f, double angle,
                              const std::string& detail) {
        std::ostringstream s;
        s << p << "::" << f << " refused rotation angle " << angle << " rad";
        if (!detail.empty()) s << " (" << detail << ")";
        return s.str();
    }
    std::string parameterization_;
    std::string function_;
    double angle_;
};

class SolverError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

[[noreturn]] void verify_failed(const char* condition, const std::string& message,
                                const char* file, int line);

}  // namespace rotbeam

#define ROTBEAM_VERIFY(cond, msg)                                                  \
    do {                                                                           \
        if (!(cond)) ::rotbeam::verify_failed(#cond, (msg), __FILE__, __LINE__);   \
    } while (false)
