#!/usr/bin/env bash
# Realistic mistakes planted one at a time in the path tracer (chapter "Testing the
# renderer"): each is a one-line edit of src/render/, made in place, followed by the
# renderer's tests (`cargo test --test book renderer::`); the file is restored after each.
# Writes figures/render_mistakes.md: each mistake, and the tests that failed.
#
#   tools/mutants/mistakes.sh          (run it in a clean checkout: it edits files in place)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cd "$root"
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "mistakes.sh edits files in place: run it in a clean checkout (git worktree add ...)" >&2
  exit 2
fi
# name | what, in words | file | sed expression
mistakes=(
  "mis-mixed|MIS weights that do not sum to one: BSDF-sampled hits weighted by the balance heuristic, light samples by the power heuristic|src/render/integrator.rs|s/                            h.weight(pb, pl)/                            crate::transport::shadow::Heuristic::Balance.weight(pb, pl)/"
  "direct-1pct|the direct-lighting (shadow-ray) term 1 % too bright|src/render/integrator.rs|s/\* cos \* w \/ pl;/* cos * w \/ pl * 1.01;/"
  "pick-bsdf|the light-selection probability left out of the MIS density of BSDF-sampled hits|src/render/integrator.rs|s/let pl = light_choice \* scene.lights\[k\].light().pdf(o, d);/let pl = scene.lights[k].light().pdf(o, d);/"
  "pick-nee|the light-selection probability left out of the shadow ray's density|src/render/integrator.rs|s/let pl = light_choice \* ls.pdf;/let pl = ls.pdf;/"
  "fresnel-95|a dielectric that reflects with probability 0.95 F instead of F|src/render/integrator.rs|s/>= f =>/>= 0.95 * f =>/"
  "no-cosine|the cosine of the shadow ray left out of next-event estimation|src/render/integrator.rs|s/\* le\[j\] \* cos \* w \/ pl;/* le[j] * w \/ pl;/"
  "two-sided-light|a shadow ray that counts a quad light's back side|src/render/integrator.rs|s/&& ls.cos_light < 0.0/\&\& ls.cos_light != 0.0/"
  "roulette-undivided|Russian roulette that kills paths without dividing the survivors by the survival probability|src/render/integrator.rs|s/\*b = roulette(\*b, q, u);/*b = if u < q { *b } else { 0.0 };/"
  "film-undivided|a thin film's reflected lanes weighted by R instead of R \/ P|src/render/integrator.rs|s/beta\[j\] \*= resp\[j\].0 \/ p_r;/beta[j] *= resp[j].0;/"
  "no-termination|dispersion without terminating the secondary wavelengths|src/render/integrator.rs|s/wl.terminate_secondary();/let _ = \&wl;/"
  "first-light|next-event estimation that always picks the first light|src/render/integrator.rs|s/((u_pick \* scene.lights.len() as f64) as usize).min(scene.lights.len() - 1)/0usize.max(u_pick as usize)/"
  "uniform-pdf|BSDF samples drawn cosine-weighted but given the uniform hemisphere's density in MIS|src/render/integrator.rs|s/bsdf_pdf = Some(local.z \* FRAC_1_PI);/bsdf_pdf = Some(0.5 * FRAC_1_PI);/"
  "sky-backwards|the sky looked up in the direction the ray came from|src/render/integrator.rs|s/env.eval(d, wl.lambda\[j\])/env.eval(-d, wl.lambda[j])/"
  "no-jitter|every camera ray through the pixel's centre (no box filter)|src/render/pixel.rs|s/let jitter = DVec2::new(rng.random(), rng.random());/let jitter = DVec2::new(0.5 + 0.0 * rng.random::<f64>(), 0.5 + 0.0 * rng.random::<f64>());/"
  "lanes-not-averaged|the hero estimator summed over the lanes instead of averaged|src/render/pixel.rs|s/sum \/ (N as f64 \* cie::y_integral())/sum \/ cie::y_integral()/"
)
export CARGO_TERM_COLOR=never
table="$root/figures/render_mistakes.md.tmp"
{
  echo "| mistake | tests of \`renderer::\` that fail |"
  echo "|---|---|"
} > "$table"
for m in "${mistakes[@]}"; do
  IFS='|' read -r name what file expr <<< "$m"
  cp "$file" "$file.orig"
  sed -i "$expr" "$file"
  if cmp -s "$file" "$file.orig"; then
    mv "$file.orig" "$file"
    echo "mistakes.sh: the edit of $name changed nothing in $file" >&2
    rm -f "$table"
    exit 1
  fi
  echo "== $name"
  set +e
  out="$(cargo test --test book renderer:: 2>&1)"
  status=$?
  set -e
  mv "$file.orig" "$file"
  if ! grep -q "^test result" <<< "$out"; then
    echo "$out" | tail -20 >&2
    echo "mistakes.sh: $name did not build" >&2
    rm -f "$table"
    exit 1
  fi
  failed="$( (grep -E '^test .* FAILED$' <<< "$out" || true) | sed -E 's/^test renderer::([a-z_]+::)*([a-z_0-9]+) .*/`\2`/' | sort -u | paste -sd, - | sed 's/,/, /g')"
  [ "$status" -ne 0 ] || failed="**none: not caught**"
  echo "| $what | $failed |" >> "$table"
done
echo >> "$table"
echo "*Each mistake is a one-line edit of \`src/render/\` (\`tools/mutants/mistakes.sh\`, which lists them), planted alone; the tests are those of \`cargo test --test book renderer::\`.*" >> "$table"
mv "$table" "$root/figures/render_mistakes.md"
cat "$root/figures/render_mistakes.md"
