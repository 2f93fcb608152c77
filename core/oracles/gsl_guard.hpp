// RAII switch-off of GSL's default error handler (which aborts the process): the reference code
// checks every GSL return code itself. The previous handler is restored on scope exit. GSL's
// handler is process-global, so concurrent threads that rely on the aborting handler would see it
// off meanwhile; rotbeam never relies on it.
#pragma once

#include <gsl/gsl_errno.h>

namespace rotbeam {

class GslErrorHandlerOff {
  public:
    GslErrorHandlerOff() : previous_(gsl_set_error_handler_off()) {}
    ~GslErrorHandlerOff() { gsl_set_error_handler(previous_); }
    GslErrorHandlerOff(const GslErrorHandlerOff&) = delete;
    GslErrorHandlerOff& operator=(const GslErrorHandlerOff&) = delete;

  private:
    gsl_error_handler_t* previous_;
};

}  // namespace rotbeam
