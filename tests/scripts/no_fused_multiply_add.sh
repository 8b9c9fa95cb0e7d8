#!/usr/bin/env bash
# The command-line binaries hold no fused multiply-add instruction (x86): a lane's bits rest on
# every product and sum being rounded on its own (docs/numerics.md), which -ffp-contract=off alone
# does not ensure (GCC 12's vectoriser can still fuse a p + q, p − q pair of products).
# Usage: no_fused_multiply_add.sh BINARY...
set -euo pipefail
status=0
for binary in "$@"; do
  count=$(objdump -d --no-show-raw-insn "$binary" | grep -cE '[[:space:]]vfn?m(add|sub)' || true)
  if [ "$count" != 0 ]; then
    echo "$binary: $count fused multiply-add instructions:"
    objdump -dC --no-show-raw-insn "$binary" |
      awk '/^[0-9a-f]+ <.*>:$/ { f = $0 } /[[:space:]]vfn?m(add|sub)/ { print "  in " f }' | sort -u | head -5
    status=1
  else
    echo "$binary: no fused multiply-add"
  fi
done
exit $status
