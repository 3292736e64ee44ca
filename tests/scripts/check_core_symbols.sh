#!/usr/bin/env bash
# Fails when a static library references the heap or the exception machinery.
#
#   check_core_symbols.sh LIBRARY [NM]
#
# Lists the undefined symbols of every object in LIBRARY (nm -C --undefined-only) and rejects
# references to the C allocator (malloc, calloc, realloc, free, aligned_alloc, posix_memalign,
# memalign, valloc, pvalloc, reallocarray, strdup, strndup), to operator new / operator delete,
# to the exception runtime (__cxa_allocate_exception, __cxa_throw, __cxa_rethrow,
# __cxa_begin_catch, __cxa_end_catch, __gxx_personality_v0, _Unwind_Resume) and to libstdc++'s
# throwing helpers (std::__throw_*). fsw_core is compiled with -fno-exceptions -fno-rtti and uses
# fixed-size storage only, so none of these may appear; _Unwind_Resume would mean some object
# was built with unwind tables for exceptions, which is also a violation.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 LIBRARY [NM]" >&2
  exit 2
fi
library=$1
nm_tool=${2:-}
nm_tool=${nm_tool:-nm}

if [[ ! -f "$library" ]]; then
  echo "error: no such library: $library" >&2
  exit 2
fi

if ! listing=$("$nm_tool" -C -A --undefined-only "$library"); then
  echo "error: $nm_tool failed on $library" >&2
  exit 2
fi

# Exact C names.
forbidden_exact='^(malloc|calloc|realloc|reallocarray|free|aligned_alloc|posix_memalign|memalign|valloc|pvalloc|strdup|strndup|__cxa_allocate_exception|__cxa_free_exception|__cxa_throw|__cxa_rethrow|__cxa_begin_catch|__cxa_end_catch|__cxa_get_exception_ptr|__gxx_personality_v0|_Unwind_Resume)$'
# Demangled C++ names, by prefix.
forbidden_prefix='^(operator new|operator delete|std::__throw_)'

violations=""
while IFS= read -r line; do
  [[ -z "$line" ]] && continue
  # "archive:member.o:                 U symbol"  ->  where = archive:member.o, symbol = symbol
  symbol=${line##*" U "}
  where=${line%%" "*}
  where=${where%:}
  if [[ "$symbol" =~ $forbidden_exact || "$symbol" =~ $forbidden_prefix ]]; then
    violations+="  ${where}: ${symbol}"$'\n'
  fi
done <<< "$listing"

if [[ -n "$violations" ]]; then
  echo "FAIL: $library references allocator or exception symbols:"
  printf '%s' "$violations"
  exit 1
fi

objects=$(grep -c '' <<< "$("$nm_tool" -A "$library" 2>/dev/null | cut -d: -f2 | sort -u)" || true)
echo "OK: $library ($objects object files) references no allocator or exception symbols"
