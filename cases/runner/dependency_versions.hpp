// The dependencies' versions, one per line, for `rotbeam --version`.
#pragma once

#include <string>

namespace rotbeam::cli {

std::string dependency_versions();

}  // namespace rotbeam::cli
