//! The Kolmogorov–Smirnov test.
//!
//! The empirical CDF of `n` samples, `F_n(x) = #{samples <= x} / n`, is compared with the
//! claimed CDF `F` at every point: `D_n = sup_x |F_n(x) - F(x)|`. For a continuous `F`
//! the law of `D_n` under the null does not depend on `F` at all (substitute `u = F(x)`:
//! the samples become uniform), so one table serves every distribution, and no binning
//! is needed.
//!
//! P-values: for `n <= 1000`, the exact distribution of `D_n`: by the matrix method of
//! Marsaglia, Tsang & Wang, "Evaluating Kolmogorov's distribution", *Journal of
//! Statistical Software* 8(18), 2003, in the body, and by twice Smirnov's one-sided tail
//! (Birnbaum & Tingey 1951) in the far right tail, where `1 - P(D_n < d)` would cancel
//! (Simard & L'Ecuyer, *J. Stat. Softw.* 39(11), 2011, do the same far out). For larger
//! `n`, Kolmogorov's limit law evaluated at `(sqrt(n) + 0.12 + 0.11 / sqrt(n)) D`, the
//! correction of Stephens (1970) that makes it accurate for moderate `n`. Two samples get
//! the exact p-value by a path count up to `n_a n_b = 10^7`, and the limit law beyond.

use super::StatsError;

/// The outcome of a Kolmogorov–Smirnov test.
#[derive(Clone, Debug, PartialEq)]
pub struct Ks {
    /// The statistic `D = sup |F_n - F|` (or `sup |F_a - F_b|` for two samples).
    pub statistic: f64,
    /// Number of samples (for two samples: the effective `n = n_a n_b / (n_a + n_b)`,
    /// rounded down).
    pub n: usize,
    /// `P(D >= statistic)` under the null hypothesis.
    pub p_value: f64,
}

/// Largest `n` for which [`one_sample`] computes the exact p-value.
pub const EXACT_MAX_N: usize = 1000;

/// Checks that every sample is finite; `what` names the input in the error.
fn check_finite(samples: &[f64], what: &'static str) -> Result<(), StatsError> {
    if samples.is_empty() {
        return Err(StatsError::Empty { what });
    }
    match samples.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(StatsError::NonFiniteSample {
            what,
            index: index as u64,
            value: samples[index],
        }),
        None => Ok(()),
    }
}

/// A sorted copy of `samples`, in the order of [`f64::total_cmp`].
///
/// Sorted as the integers `total_cmp` itself compares: the bits as a signed integer, with
/// the magnitude bits of negative numbers flipped, so that the integer order is the
/// floating-point order (`-0` just before `+0`). The same order, so the same sorted
/// values, but the standard library sorts plain integers about a third faster than
/// floats through a comparison function, and the tests sort millions of samples.
fn sorted(samples: &[f64]) -> Vec<f64> {
    // An involution: the sign bit, which chooses the flip, is left as it is.
    let key = |bits: u64| {
        let b = bits as i64;
        b ^ (((b >> 63) as u64) >> 1) as i64
    };
    let mut keys: Vec<i64> = samples.iter().map(|x| key(x.to_bits())).collect();
    keys.sort_unstable();
    keys.into_iter()
        .map(|k| f64::from_bits(key(k as u64) as u64))
        .collect()
}

// ANCHOR: statistic
/// One-sample Kolmogorov–Smirnov test of `samples` against the continuous CDF `cdf`.
///
/// With the samples sorted, `x_(1) <= … <= x_(n)`, the empirical CDF jumps from
/// `(i-1)/n` to `i/n` at `x_(i)` and `F` is non-decreasing, so the supremum is attained
/// at a jump: `D = max_i max(i/n - F(x_(i)), F(x_(i)) - (i-1)/n)`. The p-value is
/// [`p_value`]`(n, D)`. The input is not modified (a copy is sorted).
///
/// # Errors
/// [`StatsError::Empty`] for no samples, [`StatsError::NonFiniteSample`] for a NaN or
/// infinite sample (with its index in `samples`), [`StatsError::CdfOutOfRange`] if `cdf`
/// returns NaN or a value outside `[0, 1]` at a sample, [`StatsError::CdfNotMonotone`]
/// if it decreases between two samples.
pub fn one_sample(samples: &[f64], cdf: impl Fn(f64) -> f64) -> Result<Ks, StatsError> {
    check_finite(samples, "samples")?;
    let xs = sorted(samples);
    let n = xs.len();
    let nf = n as f64;
    let (mut d, mut previous) = (0.0f64, (f64::NEG_INFINITY, 0.0));
    for (i, &x) in xs.iter().enumerate() {
        let f = cdf(x);
        if !(0.0..=1.0).contains(&f) {
            return Err(StatsError::CdfOutOfRange { x, value: f });
        }
        if f < previous.1 {
            let (x0, f0) = previous;
            return Err(StatsError::CdfNotMonotone {
                x0,
                f0,
                x1: x,
                f1: f,
            });
        }
        previous = (x, f);
        d = d.max((i + 1) as f64 / nf - f).max(f - i as f64 / nf);
    }
    Ok(Ks {
        statistic: d,
        n,
        p_value: p_value(n, d),
    })
}
// ANCHOR_END: statistic

// ANCHOR: two_sample
/// Two-sample Kolmogorov–Smirnov test: were `a` and `b` drawn from the same continuous
/// distribution? `D = sup_x |F_a(x) - F_b(x)|`, evaluated by walking both sorted samples
/// (tied values are stepped over together), in integers: `n_a n_b D = max |i n_b - j n_a|`
/// over the points `(i, j)` of the walk.
///
/// The p-value is exact for `n_a n_b <=` [`TWO_SAMPLE_EXACT_MAX`]
/// ([`two_sample_exact_p`], a path count); beyond, it is the limit law at the effective
/// sample size `n_a n_b / (n_a + n_b)`, with Stephens' one-sample correction, which is
/// slightly conservative.
///
/// # Errors
/// [`StatsError::Empty`] or [`StatsError::NonFiniteSample`] naming `"sample a"` or
/// `"sample b"`.
pub fn two_sample(a: &[f64], b: &[f64]) -> Result<Ks, StatsError> {
    let gap = two_sample_gap(a, b)?;
    let (na, nb) = (a.len(), b.len());
    let product = na as f64 * nb as f64;
    Ok(Ks {
        statistic: gap as f64 / product,
        n: (product / (na + nb) as f64) as usize,
        p_value: two_sample_p_value(na, nb, gap),
    })
}
// ANCHOR_END: two_sample

/// The p-value of [`two_sample`] for samples of `na` and `nb` values whose statistic is
/// `gap / (na nb)`: exact for `na nb <=` [`TWO_SAMPLE_EXACT_MAX`], else Stephens'
/// approximation.
pub fn two_sample_p_value(na: usize, nb: usize, gap: u128) -> f64 {
    let product = na as f64 * nb as f64;
    if na.saturating_mul(nb) <= TWO_SAMPLE_EXACT_MAX {
        two_sample_exact_p(na, nb, gap)
    } else {
        kolmogorov_sf(stephens_lambda(
            product / (na + nb) as f64,
            gap as f64 / product,
        ))
    }
}

/// The statistic of [`two_sample`] in integers, `n_a n_b D = max |i n_b - j n_a|` over the
/// points `(i, j)` of the walk through both sorted samples (tied values stepped over
/// together): the `gap` of [`two_sample_exact_p`].
///
/// # Errors
/// As [`two_sample`].
pub fn two_sample_gap(a: &[f64], b: &[f64]) -> Result<u128, StatsError> {
    check_finite(a, "sample a")?;
    check_finite(b, "sample b")?;
    let (a, b) = (sorted(a), sorted(b));
    let (na, nb) = (a.len(), b.len());
    let (mut i, mut j, mut gap) = (0, 0, 0u128);
    while i < na && j < nb {
        let x = a[i].min(b[j]);
        while i < na && a[i] == x {
            i += 1;
        }
        while j < nb && b[j] == x {
            j += 1;
        }
        gap = gap.max(lattice_gap(na, nb, i, j));
    }
    // Past the end of one sample the difference only shrinks towards 0: no need to go on.
    Ok(gap)
}

/// `|i n_b - j n_a|`: `n_a n_b` times the gap `|i / n_a - j / n_b|` between the two
/// empirical CDFs after `i` values of `a` and `j` of `b`, exactly.
fn lattice_gap(na: usize, nb: usize, i: usize, j: usize) -> u128 {
    let (left, right) = (i as u128 * nb as u128, j as u128 * na as u128);
    left.abs_diff(right)
}

/// Largest `n_a n_b` for which [`two_sample`] computes the exact p-value (the path count
/// costs at most `n_a n_b` steps: 60 200 for 200 and 301 samples, of which it visits only
/// the band of points within the gap).
pub const TWO_SAMPLE_EXACT_MAX: usize = 10_000_000;

// ANCHOR: two_sample_exact
/// The exact `P(D >= d)` of the two-sample statistic under the null, for `n_a` and `n_b`
/// samples and `n_a n_b d = gap` (an integer, as [`two_sample`] computes it).
///
/// Under the null the merged, sorted sample is a uniformly random arrangement of `n_a`
/// values of `a` and `n_b` of `b`: a lattice path from `(0, 0)` to `(n_a, n_b)` whose steps
/// take the next value of `a` (probability `(n_a - i) / (n - i - j)` at `(i, j)`, `n = n_a +
/// n_b`) or of `b`. `D >= d` exactly when the path reaches a point with
/// `|i n_b - j n_a| >= gap`. The probability of reaching each point without having done so
/// is carried row by row (Hodges 1958; Kim and Jennrich 1973 count the same paths), and the
/// p-value is the sum of the probabilities of the first such points: a sum of positive
/// terms, which keeps its relative accuracy far out in the tail, where `1 - P(D < d)` would
/// not.
pub fn two_sample_exact_p(na: usize, nb: usize, gap: u128) -> f64 {
    if gap == 0 || na == 0 || nb == 0 {
        return 1.0;
    }
    let n = na + nb;
    // The points of row i within the gap, |i n_b - j n_a| < gap: the j from `lo` to `hi`.
    // Only they carry probability; the walk of a row visits them and the one past `hi`
    // (a step in b can reach it), starting from the previous row's `lo`.
    let (wa, wb) = (na as u128, nb as u128);
    let band = |i: usize| {
        let left = i as u128 * wb;
        let lo = if left < gap { 0 } else { (left - gap) / wa + 1 };
        let hi = ((left + gap - 1) / wa).min(wb);
        (lo as usize, hi as usize)
    };
    let mut row = vec![0.0f64; nb + 1];
    row[0] = 1.0;
    let mut reached = 0.0;
    let mut from = 0;
    for i in 0..=na {
        let (lo, hi) = band(i);
        // The mass at (i, j - 1), carried from one point to the next.
        let mut previous = if from > 0 { row[from - 1] } else { 0.0 };
        let last = (hi + 1).min(nb);
        for (j, cell) in row.iter_mut().enumerate().take(last + 1).skip(from) {
            let mut mass = *cell;
            if j > 0 {
                // A step in b from (i, j - 1).
                mass += previous * (nb - (j - 1)) as f64 / (n - i - (j - 1)) as f64;
            }
            // Outside the band exactly when `|i n_b - j n_a| >= gap`.
            if j < lo || j > hi {
                reached += mass;
                mass = 0.0;
            }
            *cell = mass;
            previous = mass;
        }
        if i < na {
            // A step in a from each (i, j) within the gap to (i + 1, j).
            for (j, mass) in row.iter_mut().enumerate().take(hi + 1).skip(lo) {
                *mass *= (na - i) as f64 / (n - i - j) as f64;
            }
        }
        from = lo;
    }
    reached.min(1.0)
}
// ANCHOR_END: two_sample_exact

/// Stephens' scaled statistic `(sqrt(n) + 0.12 + 0.11 / sqrt(n)) d`.
fn stephens_lambda(n: f64, d: f64) -> f64 {
    let s = n.sqrt();
    (s + 0.12 + 0.11 / s) * d
}

// ANCHOR: p_value
/// `P(D_n >= d)` for the one-sample statistic of `n` samples.
///
/// For `n <=` [`EXACT_MAX_N`] it is exact: `1 -` [`kolmogorov_cdf`]`(n, d)` (the matrix
/// method) in the body of the distribution, `n d² <= 3`; beyond, where `1 - P(D_n < d)`
/// would lose its relative accuracy to cancellation and the matrix grows, it is
/// `2 ·` [`smirnov_upper_tail`]`(n, d)`. That doubles the one-sided tail, counting twice
/// the event that *both* `D+` and `D-` reach `d`; that event is impossible for `d > 1/2`
/// and, for `n d² > 3`, relatively smaller than `1e-7` (a test asserts it), so the
/// result is exact to that accuracy and never smaller than the truth.
///
/// For `n >` [`EXACT_MAX_N`]: Kolmogorov's limit law at Stephens' scaled statistic,
/// [`kolmogorov_sf`]`((sqrt(n) + 0.12 + 0.11/sqrt(n)) d)`.
pub fn p_value(n: usize, d: f64) -> f64 {
    if n == 0 || d.is_nan() {
        return f64::NAN;
    }
    let nf = n as f64;
    if n > EXACT_MAX_N {
        return kolmogorov_sf(stephens_lambda(nf, d));
    }
    if d * d * nf > 3.0 {
        (2.0 * smirnov_upper_tail(n, d)).min(1.0)
    } else {
        (1.0 - kolmogorov_cdf(n, d)).clamp(0.0, 1.0)
    }
}
// ANCHOR_END: p_value

// ANCHOR: smirnov
/// Smirnov's one-sided upper tail `P(D+_n >= d)`, `D+_n = sup (F_n - F)`, by the
/// formula of Birnbaum & Tingey (1951):
///
/// `P(D+_n >= d) = d Σ_{j=0}^{⌊n(1-d)⌋} C(n, j) (1 - d - j/n)^(n-j) (d + j/n)^(j-1)`.
///
/// Every term is positive, so there is no cancellation; the terms are summed from their
/// logarithms (binomial coefficients of `n = 1000` overflow `f64`). `O(n)` work.
pub fn smirnov_upper_tail(n: usize, d: f64) -> f64 {
    if n == 0 || d.is_nan() {
        return f64::NAN;
    }
    if d <= 0.0 {
        return 1.0;
    }
    if d > 1.0 {
        return 0.0;
    }
    let nf = n as f64;
    // j <= n (1 - d) < n; the cap guards against rounding for tiny d.
    let last = ((nf * (1.0 - d)).floor() as usize).min(n - 1);
    let mut ln_choose = 0.0f64;
    let logs: Vec<f64> = (0..=last)
        .map(|j| {
            if j > 0 {
                ln_choose += ((n - j + 1) as f64 / j as f64).ln();
            }
            let jf = j as f64;
            let rest = (1.0 - d - jf / nf).max(0.0); // >= 0 but for rounding
            ln_choose + (nf - jf) * rest.ln() + (jf - 1.0) * (d + jf / nf).ln()
        })
        .collect();
    let max = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if max == f64::NEG_INFINITY {
        return 0.0;
    }
    let sum: f64 = logs.iter().map(|l| (l - max).exp()).sum();
    ((max + d.ln()).exp() * sum).clamp(0.0, 1.0)
}
// ANCHOR_END: smirnov

// ANCHOR: kolmogorov_sf
/// Kolmogorov's limit law, upper tail: `Q(λ) = lim P(sqrt(n) D_n > λ)
/// = 2 Σ_{j>=1} (-1)^(j-1) exp(-2 j² λ²)`.
///
/// That alternating series converges fast for large `λ`; for `λ < 1.18` the equivalent
/// (Jacobi theta) form `1 - Q(λ) = sqrt(2π)/λ Σ_{j>=1} exp(-(2j-1)² π² / (8 λ²))` is
/// used instead.
pub fn kolmogorov_sf(lambda: f64) -> f64 {
    if lambda.is_nan() {
        return f64::NAN;
    }
    if lambda <= 0.0 {
        return 1.0;
    }
    if lambda < 1.18 {
        let w = std::f64::consts::PI * std::f64::consts::PI / (8.0 * lambda * lambda);
        let sum: f64 = (1..=8)
            .map(|j: i32| (-f64::from((2 * j - 1).pow(2)) * w).exp())
            .sum();
        (1.0 - (std::f64::consts::TAU).sqrt() / lambda * sum).clamp(0.0, 1.0)
    } else {
        let mut sum = 0.0;
        let mut sign = 1.0;
        for j in 1..=100 {
            let term = (-2.0 * f64::from(j * j) * lambda * lambda).exp();
            sum += sign * term;
            if term <= 1e-17 * sum {
                break;
            }
            sign = -sign;
        }
        (2.0 * sum).clamp(0.0, 1.0)
    }
}
// ANCHOR_END: kolmogorov_sf

// ANCHOR: mtw
/// `P(D_n < d)`, exactly (to rounding), by Marsaglia, Tsang & Wang (2003).
///
/// Write `n d = k - h` with `k` a positive integer and `0 < h <= 1`, and `m = 2k - 1`.
/// Durbin's matrix `H` (m × m) has entries `1/(i - j + 1)!` where `i - j + 1 >= 0` (zero
/// above the first superdiagonal), except that the first column and the last row are
/// corrected for the fractional part `h`: `H[i][0] = (1 - h^(i+1)) / (i+1)!`,
/// `H[m-1][j] = (1 - h^(m-j)) / (m-j)!`, and the corner receives both corrections plus
/// `(2h - 1)^m / m!` when `2h > 1`. Then
///
/// `P(D_n < d) = n! / n^n · (H^n)[k-1][k-1]`.
///
/// `H^n` is formed by repeated squaring. Its entries grow like `e^n`, so each product is
/// rescaled by an exact power of two whenever it exceeds `2^400`, and the exponents are
/// carried separately; the factor `n!/n^n` is applied one ratio `i/n` at a time with the
/// same bookkeeping. The cost is `O(m³ log n)`: cheap for the `d` a test meets under the
/// null, expensive for large `n d` (where [`p_value`] uses [`smirnov_upper_tail`] instead).
pub fn kolmogorov_cdf(n: usize, d: f64) -> f64 {
    if n == 0 || d.is_nan() {
        return f64::NAN;
    }
    let nf = n as f64;
    if d >= 1.0 {
        return 1.0;
    }
    if d <= 0.5 / nf {
        return 0.0; // D_n >= 1/(2n) always
    }
    let k = (nf * d).floor() as usize + 1;
    let m = 2 * k - 1;
    let h = k as f64 - nf * d;

    // inverse_factorial[i] = 1 / i!
    let mut inverse_factorial = vec![1.0f64; m + 1];
    for i in 1..=m {
        inverse_factorial[i] = inverse_factorial[i - 1] / i as f64;
    }
    let mut a = Matrix::zeros(m);
    for i in 0..m {
        for j in 0..m {
            if i + 1 >= j {
                a.set(i, j, 1.0);
            }
        }
    }
    for i in 0..m {
        a.add(i, 0, -h.powi(i as i32 + 1));
        a.add(m - 1, i, -h.powi((m - i) as i32));
    }
    if 2.0 * h > 1.0 {
        a.add(m - 1, 0, (2.0 * h - 1.0).powi(m as i32));
    }
    for i in 0..m {
        for j in 0..m {
            if i + 1 >= j {
                let v = a.get(i, j) * inverse_factorial[i + 1 - j];
                a.set(i, j, v);
            }
        }
    }

    let (q, mut exponent) = power(&a, n);
    let mut s = q.get(k - 1, k - 1);
    for i in 1..=n {
        s *= i as f64 / nf;
        if s < TINY {
            s *= HUGE;
            exponent -= SCALE_BITS;
        }
    }
    (s * 2f64.powi(exponent)).clamp(0.0, 1.0)
}
// ANCHOR_END: mtw

/// Rescaling step of the matrix power: `2^SCALE_BITS`, about `1e120`.
const SCALE_BITS: i32 = 400;
const HUGE: f64 = f64::from_bits(((1023 + SCALE_BITS) as u64) << 52); // 2^400, exactly
const TINY: f64 = 1.0 / HUGE;

/// A dense square matrix, row-major.
#[derive(Clone)]
struct Matrix {
    m: usize,
    v: Vec<f64>,
}

impl Matrix {
    fn zeros(m: usize) -> Self {
        Self {
            m,
            v: vec![0.0; m * m],
        }
    }
    fn identity(m: usize) -> Self {
        let mut id = Self::zeros(m);
        for i in 0..m {
            id.set(i, i, 1.0);
        }
        id
    }
    fn get(&self, i: usize, j: usize) -> f64 {
        self.v[i * self.m + j]
    }
    fn set(&mut self, i: usize, j: usize, x: f64) {
        self.v[i * self.m + j] = x;
    }
    fn add(&mut self, i: usize, j: usize, x: f64) {
        self.v[i * self.m + j] += x;
    }
    fn mul(&self, other: &Self) -> Self {
        let m = self.m;
        let mut out = Self::zeros(m);
        for i in 0..m {
            let row = &mut out.v[i * m..(i + 1) * m];
            for l in 0..m {
                let x = self.v[i * m + l];
                if x != 0.0 {
                    for (r, &y) in row.iter_mut().zip(&other.v[l * m..(l + 1) * m]) {
                        *r += x * y;
                    }
                }
            }
        }
        out
    }
    /// Divides by `2^SCALE_BITS` while any entry exceeds it; returns the bits removed.
    fn rescale(&mut self) -> i32 {
        let mut removed = 0;
        while self.v.iter().any(|x| x.abs() > HUGE) {
            for x in &mut self.v {
                *x *= TINY;
            }
            removed += SCALE_BITS;
        }
        removed
    }
}

/// `a^n` as `(matrix, e)` meaning `matrix * 2^e`, by repeated squaring.
fn power(a: &Matrix, mut n: usize) -> (Matrix, i32) {
    let (mut result, mut result_e) = (Matrix::identity(a.m), 0);
    let (mut base, mut base_e) = (a.clone(), 0);
    loop {
        if n & 1 == 1 {
            result = result.mul(&base);
            result_e += base_e + result.rescale();
        }
        n >>= 1;
        if n == 0 {
            return (result, result_e);
        }
        base = base.mul(&base);
        base_e = 2 * base_e + base.rescale();
    }
}
