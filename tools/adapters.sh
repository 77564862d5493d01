# Shared by the scripts that run other renderers (tools/mitsuba, tools/blender,
# tools/luxcore): sourced, never run. One copy of each small job they all do.
#
#     source "$(dirname "$0")/../adapters.sh"

# pinned_venv VENV PYTHON PACKAGE==VERSION...: the venv VENV (made with PYTHON if missing)
# holding exactly these versions of these packages; installs them if any differs.
pinned_venv() {
    local venv="$1" python="$2"
    shift 2
    local py="$venv/bin/python" want="" names=""
    local spec
    for spec in "$@"; do
        want="$want ${spec#*==}"
        names="$names \"${spec%%==*}\","
    done
    if [ ! -x "$py" ]; then
        echo "creating venv $venv" >&2
        "$python" -m venv "$venv"
    fi
    local have
    have="$("$py" -c "import importlib.metadata as m
try:
    print(' ' + ' '.join(m.version(n) for n in [$names]))
except m.PackageNotFoundError:
    print('')" 2>/dev/null || true)"
    if [ "$have" != "$want" ]; then
        echo "installing $* into $venv" >&2
        "$py" -m pip install --quiet --disable-pip-version-check "$@"
    fi
}

# ladder_options DEFAULT_SPP [--table] [SPP [RUNS]]: sets table_only (1 with --table: the
# table again from the last cards), spp and runs (default 4) from a script's arguments.
ladder_options() {
    local default_spp="$1"
    shift
    table_only=0
    if [ "${1:-}" = "--table" ]; then
        table_only=1
        shift
    fi
    spp="${1:-$default_spp}"
    runs="${2:-4}"
}

# raylemma_release ROOT: builds raylemma's release binary from the clone ROOT and prints
# its path.
raylemma_release() {
    (cd "$1" && cargo build --release --quiet -p raylemma)
    echo "${CARGO_TARGET_DIR:-$1/target}/release/raylemma"
}

# machine_cpu: this machine's processor, as /proc/cpuinfo names it.
machine_cpu() {
    grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'
}

# json_card ROOT WORK RENDERER: the conformance card of RENDERER (a command with raylemma's
# placeholders) on every rung, the scenes exported as JSON, at $spp and $runs, into a fresh
# WORK (card.json, card.txt, card.log); prints the card's last lines. A card that differs
# is what these scripts study, so its exit status is not an error here.
json_card() {
    local root="$1" work="$2" renderer="$3"
    rm -rf "$work"
    mkdir -p "$work"
    (cd "$root" && "$RAYLEMMA" conformance --format json --spp "$spp" --runs "$runs" \
        --work "$work" --json "$work/card.json" --renderer "$renderer" \
        > "$work/card.txt" 2> "$work/card.log") || true
    tail -n 3 "$work/card.txt" >&2
}
