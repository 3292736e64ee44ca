// Canary of Core_ModuleGraphCheckRejectsForbiddenDependencies: a "table" module object that calls
// a function of the "optimizer" module (module_graph_canary.sh); the symbol view must flag it.
namespace tolip_canary {
double optimizer_payoff(double x);
double table_entry(double x) { return optimizer_payoff(x) + 1.0; }
}  // namespace tolip_canary
