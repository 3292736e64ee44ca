// Canary of Core_ModuleGraphCheckRejectsForbiddenDependencies: the "optimizer" module object that
// defines what the canary table object calls.
namespace tolip_canary {
double optimizer_payoff(double x) { return 2.0 * x; }
}  // namespace tolip_canary
