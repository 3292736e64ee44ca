#!/usr/bin/env bash
# Proves the cross-compiled core and the flight image are freestanding (docs/target.md):
#
#   check_freestanding.sh CORE_LIBRARY FLIGHT_ELF LINKER_SCRIPT NM CORE_CHECK_SCRIPT
#
#   1. The core library's objects reference no allocator or exception symbol: the host check
#      (tests/scripts/check_core_symbols.sh) run with the cross nm, plus newlib's reentrant
#      allocator entry points and _sbrk.
#   2. The linked image contains no allocator (malloc, free, _malloc_r, _sbrk, ...), no printf
#      family (newlib's printf allocates through _dtoa_r / _malloc_r), no exception runtime, and
#      defines none of the symbols a heap would start at (end, _end, __end__, __heap_start).
#   3. The linker script declares no heap region.
set -euo pipefail

if [[ $# -ne 5 ]]; then
  echo "usage: $0 CORE_LIBRARY FLIGHT_ELF LINKER_SCRIPT NM CORE_CHECK_SCRIPT" >&2
  exit 2
fi
library=$1 elf=$2 script=$3 nm_tool=$4 core_check=$5
for file in "$library" "$elf" "$script" "$core_check"; do
  [[ -f "$file" ]] || { echo "error: no such file: $file" >&2; exit 2; }
done

# 1. The core library.
bash "$core_check" "$library" "$nm_tool"
extra=$("$nm_tool" -A --undefined-only "$library" |
        awk '{print $NF}' |
        grep -E '^(_sbrk|_sbrk_r|_malloc_r|_calloc_r|_realloc_r|_free_r|_memalign_r|__cxa_guard_acquire)$' || true)
if [[ -n "$extra" ]]; then
  echo "FAIL: $library references allocator or exception symbols:"
  echo "$extra" | sed 's/^/  /'
  exit 1
fi

# 2. The linked image.
forbidden='^(malloc|free|calloc|realloc|reallocarray|aligned_alloc|posix_memalign|memalign|_malloc_r|_free_r|_calloc_r|_realloc_r|_sbrk|_sbrk_r|printf|vprintf|fprintf|vfprintf|sprintf|snprintf|vsnprintf|_printf_r|_vfprintf_r|_svfprintf_r|_vfiprintf_r|_dtoa_r|puts|fputs|fwrite|_fwrite_r|__sinit|atexit|__register_exitproc|__cxa_allocate_exception|__cxa_throw|__cxa_begin_catch|__gxx_personality_v0|_Unwind_Resume|end|_end|__end__|__heap_start|__HeapBase|__HeapLimit|_Znwj|_Znaj|_ZdlPv|_ZdaPv|_ZdlPvj)$'
found=$("$nm_tool" "$elf" | awk '{print $NF}' | grep -E "$forbidden" | sort -u || true)
if [[ -n "$found" ]]; then
  echo "FAIL: $elf contains allocator, printf or exception symbols:"
  echo "$found" | sed 's/^/  /'
  exit 1
fi

# 3. The linker script (comments removed): no heap.
body=$(sed -e ':a' -e 's#/\*[^*]*\*\+\([^/*][^*]*\*\+\)*/##g' -e '/\/\*/{N;ba' -e '}' "$script")
if grep -qiE 'heap|(^|[^_a-zA-Z])_?end[[:space:]]*=' <<< "$body"; then
  echo "FAIL: $script declares a heap region or a heap start symbol:"
  grep -niE 'heap|(^|[^_a-zA-Z])_?end[[:space:]]*=' <<< "$body" | sed 's/^/  /'
  exit 1
fi

table=$("$nm_tool" "$elf" | awk '$3 == "tolip_pitch_table" {print $1}')
echo "OK: $library and $elf are freestanding (no allocator, printf or exception symbols; no heap in $(basename "$script")); tolip_pitch_table at 0x${table:-?}"
