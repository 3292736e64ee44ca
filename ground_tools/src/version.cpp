#include "tolip_ground/version.hpp"
namespace tolip::ground {
const char* version_string() { return "0.1.0"; }
}  // namespace tolip::ground
