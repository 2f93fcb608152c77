// `rotbeam --version`: the versions of the dependencies the program was built with, from their
// headers' version macros; yaml-cpp's headers have none, so its CMake package's version is passed
// in at configure time (ROTBEAM_YAML_CPP_VERSION, cases/runner/CMakeLists.txt); cmark-gfm's is the
// linked library's own string (reports/report_html.cpp).
#include "dependency_versions.hpp"

#include <Spectra/Util/Version.h>
#include <gsl/gsl_version.h>
#include <klu.h>
#include <sundials/sundials_config.h>

#include <Eigen/Core>
#include <boost/version.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "SuiteSparse_config.h"
#include "reports/report.hpp"

namespace rotbeam::cli {

std::string dependency_versions() {
    std::ostringstream s;
    s << "  SUNDIALS     " << SUNDIALS_VERSION << "\n"
      << "  Eigen        " << EIGEN_WORLD_VERSION << "." << EIGEN_MAJOR_VERSION << "."
      << EIGEN_MINOR_VERSION << "\n"
      << "  GSL          " << GSL_VERSION << "\n"
      << "  yaml-cpp     " << ROTBEAM_YAML_CPP_VERSION << "\n"
      << "  SuiteSparse  " << SUITESPARSE_MAIN_VERSION << "." << SUITESPARSE_SUB_VERSION << "."
      << SUITESPARSE_SUBSUB_VERSION << " (KLU " << KLU_MAIN_VERSION << "." << KLU_SUB_VERSION << "."
      << KLU_SUBSUB_VERSION << ")\n"
      << "  Spectra      " << SPECTRA_MAJOR_VERSION << "." << SPECTRA_MINOR_VERSION << "."
      << SPECTRA_PATCH_VERSION << "\n"
      << "  Boost        " << BOOST_VERSION / 100000 << "." << BOOST_VERSION / 100 % 1000 << "."
      << BOOST_VERSION % 100 << "\n"
      << "  nlohmann/json " << NLOHMANN_JSON_VERSION_MAJOR << "." << NLOHMANN_JSON_VERSION_MINOR
      << "." << NLOHMANN_JSON_VERSION_PATCH << "\n"
      << "  cmark-gfm    " << markdown_library_version() << "\n";
    return s.str();
}

}  // namespace rotbeam::cli
