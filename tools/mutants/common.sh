# What the mutation scripts share (sourced by run.sh and render.sh, after they set `out`):
# cargo-mutants at the version the tables were made with, the refusal to mutate a checkout
# with changes in it, and `mutate`, one cargo-mutants run whose results are kept in
# $out/NAME (a run done before is not redone). The callers shard with `--shard K/N
# --sharding round-robin` (27.1.0 supports it; its default, `slice`, takes consecutive runs
# of mutants, i.e. the top of each file, not a systematic sample).
command -v cargo-mutants >/dev/null || cargo install cargo-mutants --locked --version 27.1.0
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "$(basename "$0") mutates files in place: run it in a clean checkout (git worktree add ...)" >&2
  exit 2
fi
mkdir -p "$out"

# The tests a filter names must pass on the unmutated code, once per filter and run: with
# `--baseline skip`, a test that already fails would make every mutant look caught.
passed_baseline=" "
mutate() { # name, test filter, cargo-mutants arguments...
  local name="$1" filter="$2"
  shift 2
  [ -f "$out/$name/mutants.out/outcomes.json" ] && { echo "== $name: done before"; return; }
  if [[ "$passed_baseline" != *" $filter "* ]]; then
    echo "== baseline: cargo test --test book $filter (must pass unmutated)"
    if ! cargo test -q --test book -- "$filter" > "$out/baseline.log" 2>&1; then
      tail -20 "$out/baseline.log" >&2
      echo "$(basename "$0"): the tests '$filter' fail on the unmutated code; every mutant would look caught (log: $out/baseline.log)" >&2
      exit 1
    fi
    passed_baseline+="$filter "
  fi
  echo "== $name (tests: $filter)"
  cargo mutants --in-place --no-shuffle --baseline skip --timeout 300 --build-timeout 900 \
    -o "$out/$name" "$@" -C --test=book -- "$filter" || true
}
