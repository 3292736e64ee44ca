#!/usr/bin/env bash
# Fails when an fsw_core module reaches a module the allowed graph does not give it (issue 18
# item 4; docs/architecture.md "Module graph"). The graph is fsw_core/module_graph.txt, one line
# "module : dependencies" per module; the build links each module target from it. Three views of
# the same rule are checked against it:
#
#   include  every #include "tolip/<m>/..." of a module's headers (include/tolip/<module>/) and
#            sources (src/<module>/) names the module itself or one of its listed dependencies;
#            a quoted include outside tolip/ is refused (a relative path would hide the module);
#   link     the module target's link libraries, as the configuration left them
#            (LINKS_FILE, "module|item item ..."), are listed dependencies or the graph's
#            (external) libraries;
#   symbol   no undefined symbol of the module's objects (OBJECTS_FILE, "module|file.o ...") is
#            defined by a module outside its dependencies and theirs (the call a missing include
#            or link line cannot hide).
#
# The graph itself must name known modules only, have no cycle, and cover every folder.
#
#   check_module_graph.sh GRAPH_FILE CORE_DIR LINKS_FILE OBJECTS_FILE NM
set -euo pipefail

graph=${1:?usage: check_module_graph.sh GRAPH_FILE CORE_DIR LINKS_FILE OBJECTS_FILE NM}
core_dir=${2:?usage: check_module_graph.sh GRAPH_FILE CORE_DIR LINKS_FILE OBJECTS_FILE NM}
links_file=${3:?usage: check_module_graph.sh GRAPH_FILE CORE_DIR LINKS_FILE OBJECTS_FILE NM}
objects_file=${4:?usage: check_module_graph.sh GRAPH_FILE CORE_DIR LINKS_FILE OBJECTS_FILE NM}
nm=${5:?usage: check_module_graph.sh GRAPH_FILE CORE_DIR LINKS_FILE OBJECTS_FILE NM}
for f in "$graph" "$links_file" "$objects_file"; do
  [[ -f "$f" ]] || { echo "check_module_graph.sh: no file $f" >&2; exit 2; }
done
[[ -d "$core_dir/include/tolip" ]] || { echo "check_module_graph.sh: no folder $core_dir/include/tolip" >&2; exit 2; }

findings=0
finding() { echo "$*"; findings=$((findings + 1)); }

# ---- the graph ------------------------------------------------------------------------------------
declare -A deps=()
modules=()
externals=" "
while IFS= read -r line; do
  line=${line%%#*}
  [[ "$line" == *:* ]] || continue
  name=$(echo "${line%%:*}" | tr -d ' \t')
  list=$(echo "${line#*:}" | xargs)
  if [[ "$name" == "(external)" ]]; then externals=" $list "; continue; fi
  modules+=("$name")
  deps[$name]=" $list "
done < "$graph"

for m in "${modules[@]}"; do
  for d in ${deps[$m]}; do
    [[ -n "${deps[$d]+set}" ]] || finding "graph: module $m depends on $d, which is no module of the graph"
  done
done

# Dependency closure of every module (depth-first over the graph, an explicit stack); a module in
# its own closure is a cycle.
declare -A closure=()
for m in "${modules[@]}"; do
  seen=" "
  stack=(${deps[$m]})
  while [[ ${#stack[@]} -gt 0 ]]; do
    d=${stack[-1]}; unset 'stack[-1]'
    [[ "$seen" == *" $d "* ]] && continue
    seen+="$d "
    [[ -n "${deps[$d]+set}" ]] && stack+=(${deps[$d]})
  done
  closure[$m]=$seen
  [[ "$seen" == *" $m "* ]] && finding "graph: module $m depends on itself through its dependencies (a cycle)"
done

# ---- include --------------------------------------------------------------------------------------
include_pattern='^[[:space:]]*#[[:space:]]*include[[:space:]]*([<"])([^>"]*)[>"]'
for dir in "$core_dir"/include/tolip/*/ "$core_dir"/src/*/; do
  [[ -d "$dir" ]] || continue
  m=$(basename "$dir")
  if [[ -z "${deps[$m]+set}" ]]; then
    finding "include: folder ${dir#"$core_dir"/} is no module of the graph (add its line to the graph)"
    continue
  fi
  while IFS= read -r hit; do
    file=${hit%%:*}; rest=${hit#*:}; lineno=${rest%%:*}; text=${rest#*:}
    [[ "$text" =~ $include_pattern ]] || continue
    quoted=no; [[ "${BASH_REMATCH[1]}" == '"' ]] && quoted=yes
    target=${BASH_REMATCH[2]}
    where="${file#"$core_dir"/}:$lineno"
    if [[ "$target" == tolip/*/* ]]; then
      to=${target#tolip/}; to=${to%%/*}
      if [[ "$to" != "$m" && "${deps[$m]}" != *" $to "* ]]; then
        finding "include: $where: module $m includes $target (module $m may include:${deps[$m]% })"
      fi
    elif [[ $quoted == yes || "$target" == tolip* ]]; then
      finding "include: $where: module $m includes \"$target\", which names no module (write \"tolip/<module>/...\")"
    fi
  done < <(grep -rHnE '^[[:space:]]*#[[:space:]]*include' "$dir" || true)
done

# ---- link -----------------------------------------------------------------------------------------
declare -A has_target=()
while IFS='|' read -r m items; do
  [[ -n "$m" ]] || continue
  has_target[$m]=1
  if [[ -z "${deps[$m]+set}" ]]; then finding "link: target fsw_core_$m is no module of the graph"; continue; fi
  for item in $items; do
    # $<LINK_ONLY:x>, $<BUILD_INTERFACE:x> and the like: the name inside.
    name=$(echo "$item" | sed -E 's/^(\$<[A-Z_]+:)+//; s/>+$//')
    if [[ "$name" == fsw_core_* ]]; then
      to=${name#fsw_core_}
      [[ "${deps[$m]}" == *" $to "* ]] || finding "link: target fsw_core_$m links $name (module $m may link:${deps[$m]% })"
    elif [[ "$externals" != *" $name "* ]]; then
      finding "link: target fsw_core_$m links $name, which is neither a dependency nor an external library of the graph (${externals# })"
    fi
  done
done < "$links_file"
for m in "${modules[@]}"; do
  [[ -n "${has_target[$m]+set}" ]] || finding "link: module $m of the graph has no target fsw_core_$m"
done

# ---- symbol ---------------------------------------------------------------------------------------
work=$(mktemp -d "${TMPDIR:-/tmp}/tolip-module-graph.XXXXXX")
trap 'rm -rf "$work"' EXIT
: > "$work/defined"; : > "$work/needed"
while IFS='|' read -r m objects; do
  [[ -n "$m" && -n "$objects" ]] || continue
  read -r -a files <<< "$objects"
  # Strong definitions only: inline functions and template instances (weak, W/V) are emitted by
  # every user and belong to no module.
  "$nm" -P --defined-only "${files[@]}" 2>/dev/null |
    awk -v m="$m" 'NF >= 2 && $1 !~ /:$/ && $2 ~ /^[TDBRG]$/ { print $1, m }' >> "$work/defined"
  "$nm" -P --undefined-only "${files[@]}" 2>/dev/null |
    awk -v m="$m" 'NF >= 2 && $1 !~ /:$/ { print m, $1 }' >> "$work/needed"
done < "$objects_file"
allowed_list=""
for m in "${modules[@]}"; do allowed_list+="$m${closure[$m]}"$'\n'; done
while read -r m to symbol; do
  pretty=$(echo "$symbol" | c++filt 2>/dev/null || echo "$symbol")
  finding "symbol: module $m uses $pretty, defined in module $to (module $m may use:${closure[$m]% })"
done < <(awk -v allowed="$allowed_list" '
  BEGIN { n = split(allowed, lines, "\n"); for (i = 1; i <= n; i++) { k = split(lines[i], w, " "); for (j = 2; j <= k; j++) ok[w[1] " " w[j]] = 1 } }
  FNR == NR { owner[$1] = $2; next }
  ($2 in owner) && owner[$2] != $1 && !(($1 " " owner[$2]) in ok) && !seen[$1 " " owner[$2]]++ { print $1, owner[$2], $2 }
' "$work/defined" "$work/needed")

if [[ $findings -gt 0 ]]; then
  echo "violates the module graph ($graph): $findings finding(s) above"
  exit 1
fi
echo "fsw_core follows its module graph: ${#modules[@]} modules"
