// The program's layer names the libraries' types and functions unqualified: the cli/ headers whose declarations
// do so include this one.
#pragma once

namespace circles::formats {}
namespace circles::conform {}
namespace circles::engines {}

namespace circles::cli {

using namespace circles::formats;
using namespace circles::conform;
using namespace circles::engines;

}  // namespace circles::cli
