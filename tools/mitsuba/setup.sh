#!/usr/bin/env bash
# Sets up Mitsuba 3 for tools/mitsuba (see README.md and NOTES.md). Idempotent.
#
#   tools/mitsuba/setup.sh            venv + libLLVM for the llvm_* variants, then a
#                                     tiny render in each CPU variant; prints those that work
#   tools/mitsuba/setup.sh --pip-only only the venv with the pinned packages (what compare_all.sh uses)
#   tools/mitsuba/setup.sh --no-test  venv + libLLVM, no test renders
#
# The venv is $RAYLEMMA_MITSUBA_VENV, default /root/.cache/raylemma-mitsuba-venv.
# Dr.Jit's LLVM backend dlopens libLLVM at run time; it needs LLVM >= 15, and on
# this CPU LLVM 15 and 16 abort in code generation ("Cannot select ... fminimum"),
# so this installs Debian's libllvm19 and points DRJIT_LIBLLVM_PATH at it, through a
# .pth file in the venv (any python of the venv gets it unless the variable is set).
set -euo pipefail

MITSUBA_VERSION=3.9.1
DRJIT_VERSION=1.5.0
NUMPY_VERSION=2.4.6
LLVM_PACKAGE=libllvm19

venv="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}"
py="$venv/bin/python"
mode=full
case "${1:-}" in
    -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --pip-only) mode=pip ;;
    --no-test) mode=notest ;;
    '') ;;
    *) echo "setup.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
esac

# ---- 1. the venv with the pinned packages
source "$(dirname "$0")/../adapters.sh"
pinned_venv "$venv" python3 \
    "mitsuba==$MITSUBA_VERSION" "drjit==$DRJIT_VERSION" "numpy==$NUMPY_VERSION"
[ "$mode" = pip ] && exit 0

# ---- 2. libLLVM for Dr.Jit's LLVM backend (llvm_* variants)
find_libllvm() {
    dpkg -L "$LLVM_PACKAGE" 2>/dev/null | grep -E '/libLLVM[^/]*\.so\.[0-9.]+$' | head -n 1
}
lib="$(find_libllvm || true)"
if [ -z "$lib" ] || [ ! -f "$lib" ]; then
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    echo "installing $LLVM_PACKAGE with apt-get" >&2
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get install -y -qq "$LLVM_PACKAGE" >/dev/null \
        || { $sudo apt-get update -qq && $sudo apt-get install -y -qq "$LLVM_PACKAGE" >/dev/null; }
    lib="$(find_libllvm)"
fi
echo "libLLVM: $lib ($LLVM_PACKAGE)"

# A .pth line runs at interpreter start-up, before drjit is imported (Dr.Jit reads
# DRJIT_LIBLLVM_PATH when it initialises; setting it after `import drjit` is too late).
site="$("$py" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
pth="$site/raylemma_libllvm.pth"
line="import os; os.environ.setdefault('DRJIT_LIBLLVM_PATH', '$lib')"
if [ "$(cat "$pth" 2>/dev/null || true)" != "$line" ]; then
    printf '%s\n' "$line" > "$pth"
    echo "wrote $pth" >&2
fi
echo "DRJIT_LIBLLVM_PATH=${DRJIT_LIBLLVM_PATH:-$lib}"
[ "$mode" = notest ] && exit 0

# ---- 3. a tiny render (Cornell box, 32 x 32, 16 spp) in each CPU variant, each in
# its own process (a libLLVM that fails to compile a kernel aborts the process).
tiny='
import sys, time
import mitsuba as mi
mi.set_variant(sys.argv[1])
d = mi.cornell_box()
d["sensor"]["film"]["width"] = d["sensor"]["film"]["height"] = 32
t0 = time.perf_counter()
import numpy as np
a = np.array(mi.render(mi.load_dict(d), spp=16))
s = time.perf_counter() - t0
print(f"{s:.2f} s wall (load + render), image mean {a.mean():.4f}")
'
variants="$("$py" -c 'import mitsuba as mi; print(" ".join(mi.variants()))')"
has_cuda="$("$py" -c 'import drjit as dr; print(int(dr.has_backend(dr.JitBackend.CUDA)))' 2>/dev/null || echo 0)"
working=()
echo "tiny render (mi.cornell_box(), 32 x 32, 16 spp) in each variant (llvm_*: the first run also compiles the kernels; Dr.Jit caches them in ~/.drjit):"
for v in $variants; do
    case "$v" in
        cuda_*) if [ "$has_cuda" != 1 ]; then printf '  %-28s skipped (no CUDA device)\n' "$v"; continue; fi ;;
    esac
    if out="$("$py" -c "$tiny" "$v" 2>&1)"; then
        out="$(printf '%s\n' "$out" | sed 's/\x1b\[[0-9;]*m//g')"
        printf '  %-28s ok   %s\n' "$v" "$(printf '%s\n' "$out" | tail -n 1)"
        working+=("$v")
    else
        out="$(printf '%s\n' "$out" | sed 's/\x1b\[[0-9;]*m//g')"
        printf '  %-28s FAIL %s\n' "$v" "$(printf '%s\n' "$out" | grep -m1 -E 'ERROR|Error|error' || printf '%s\n' "$out" | tail -n 1)"
    fi
done
echo "working variants: ${working[*]}"
