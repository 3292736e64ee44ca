// Version of the generator, stamped into outputs.
#pragma once
namespace tolip::ground {
const char* version_string();
}
