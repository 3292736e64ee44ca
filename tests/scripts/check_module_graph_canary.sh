#!/usr/bin/env bash
# The canary of Core_ModuleGraphCheckRejectsForbiddenDependencies: a small core in a new temporary
# folder whose flight-side "table" module breaks the graph once in each view the check has (it
# includes an optimizer header, its target links the optimizer, its object calls an optimizer
# function: TABLE_OBJECT and OPTIMIZER_OBJECT, compiled from module_graph_canary/), and the
# check run on it, which must report exactly those three findings.
#
#   check_module_graph_canary.sh TABLE_OBJECT OPTIMIZER_OBJECT NM
set -euo pipefail
table_object=${1:?usage: check_module_graph_canary.sh TABLE_OBJECT OPTIMIZER_OBJECT NM}
optimizer_object=${2:?usage: check_module_graph_canary.sh TABLE_OBJECT OPTIMIZER_OBJECT NM}
nm=${3:?usage: check_module_graph_canary.sh TABLE_OBJECT OPTIMIZER_OBJECT NM}
dir=$(mktemp -d "${TMPDIR:-/tmp}/tolip-module-graph-canary.XXXXXX")
trap 'rm -rf "$dir"' EXIT

printf '%s\n' 'core      :' 'optimizer : core' 'table     : core' '(external): Eigen3::Eigen' > "$dir/module_graph.txt"
mkdir -p "$dir/include/tolip/core" "$dir/include/tolip/optimizer" "$dir/include/tolip/table" "$dir/src/table"
printf '#pragma once\n' > "$dir/include/tolip/core/status.hpp"
printf '#pragma once\n#include "tolip/core/status.hpp"\n' > "$dir/include/tolip/optimizer/steepest_descent.hpp"
printf '#pragma once\n#include <cstdint>\n#include "tolip/core/status.hpp"\n' > "$dir/include/tolip/table/table_image.hpp"
printf '#include "tolip/table/table_image.hpp"\n#include "tolip/optimizer/steepest_descent.hpp"\n' \
  > "$dir/src/table/table_image.cpp"
printf '%s\n' 'core|Eigen3::Eigen' 'optimizer|fsw_core_core Eigen3::Eigen' \
  'table|fsw_core_core $<LINK_ONLY:fsw_core_optimizer> Eigen3::Eigen' > "$dir/links.txt"
printf '%s\n' 'core|' "optimizer|$optimizer_object" "table|$table_object" > "$dir/objects.txt"

bash "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/check_module_graph.sh" \
  "$dir/module_graph.txt" "$dir" "$dir/links.txt" "$dir/objects.txt" "$nm"
