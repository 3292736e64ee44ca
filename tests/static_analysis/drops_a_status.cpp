// Not built: StaticAnalysis_ADroppedStatusFailsTheBuild compiles it and expects the compiler to
// refuse it. A call that drops a tolip::Status ([[nodiscard]], status.hpp).
#include "tolip/core/status.hpp"

tolip::Status status_to_check();

void drops_the_status() { status_to_check(); }
