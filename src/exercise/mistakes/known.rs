//! What the hand-out knows of each typical mistake (see [`super`]): its words and the
//! fingerprint of its twin's probe. Written by the chapter's tests from the twins
//! (`RAYLEMMA_WRITE_KNOWN=1 cargo test --test book coursework::mistakes`); do not edit.

use super::Known;

/// Every typical mistake, in the book's order.
pub const KNOWN: &[Known] = &[
    Known {
        exercise: "intersect_stable",
        words: "t > 0: the source notes' first root \"greater than 0\", t_min ignored (a ray leaving a surface hits it again)",
        fingerprint: 0x5d4e9a2fedc93cc1,
    },
    Known {
        exercise: "intersect_stable",
        words: "every root counts, behind the origin too: a ray starting inside returns the root behind it",
        fingerprint: 0xefa4daca6c28b0ca,
    },
    Known {
        exercise: "intersect_stable",
        words: "always the far root (-b + sqrt(b^2 - ac)) / a: the exit, not the entry",
        fingerprint: 0xa097cbc2eb1d7d5f,
    },
    Known {
        exercise: "intersect_stable",
        words: "a = D.D taken as 1: right only for a unit direction",
        fingerprint: 0xff5a0fde7a35b971,
    },
    Known {
        exercise: "intersect_stable",
        words: "near misses counted as hits: a discriminant down to -1 % of a r^2 accepted",
        fingerprint: 0x891bcab909f1389e,
    },
    Known {
        exercise: "intersect_stable",
        words: "c = f.f - r: the radius where its square belongs",
        fingerprint: 0x09d3b4c67bd4456e,
    },
    Known {
        exercise: "intersect_stable",
        words: "f = C - O: centre and origin swapped, so the roots come out negated (the sphere found behind the ray)",
        fingerprint: 0x95127d6e6f786fd9,
    },
    Known {
        exercise: "estimate",
        words: "the mean of f(X): the division by the density q(X) left out",
        fingerprint: 0x0de8a70a29ba4681,
    },
    Known {
        exercise: "estimate",
        words: "f(X) / q(U): the density taken at the uniform number U, not at the sample X",
        fingerprint: 0x842c3f1487bce8ad,
    },
    Known {
        exercise: "estimate",
        words: "f(X) q(X): multiplied by the density where dividing belongs",
        fingerprint: 0xd8de1a855cd65352,
    },
    Known {
        exercise: "estimate",
        words: "f(X) / q(X) with no case for q(X) = 0: an infinite (or NaN) term there",
        fingerprint: 0x744d559821810aa0,
    },
    Known {
        exercise: "estimate",
        words: "a draw where q(X) = 0 skipped instead of adding 0: fewer than n terms, a biased mean",
        fingerprint: 0x33eb86f1bc514ae5,
    },
    Known {
        exercise: "estimate",
        words: "X = U drawn uniformly, yet weighted by 1 / q(X): the draws not taken from q",
        fingerprint: 0x792ee1123712b4b8,
    },
    Known {
        exercise: "estimate",
        words: "n + 1 terms (a loop over 0..=n)",
        fingerprint: 0x5d3ce30c43bb7499,
    },
    Known {
        exercise: "sphere_rejection",
        words: "the point of the ball returned without normalising it",
        fingerprint: 0x0bd75080c74e725c,
    },
    Known {
        exercise: "sphere_rejection",
        words: "no rejection: every point of the cube normalised, so the corners' directions crowd",
        fingerprint: 0xcd4b1ec7e4f23e0c,
    },
    Known {
        exercise: "sphere_rejection",
        words: "coordinate = -1 + u: the factor 2 left out, the cube [-1, 0)^3 (one octant)",
        fingerprint: 0x4f8cbcb52364a2e8,
    },
    Known {
        exercise: "sphere_rejection",
        words: "coordinate = u: [0, 1)^3 where [-1, 1)^3 belongs (one octant)",
        fingerprint: 0x4e88f78dc3f6db07,
    },
    Known {
        exercise: "sphere_rejection",
        words: "the draws counted without the accepted one (only the rejections)",
        fingerprint: 0x72e6730d53cbab73,
    },
    Known {
        exercise: "hemisphere_flip",
        words: "w returned as it is: the flip left out (the whole sphere)",
        fingerprint: 0xeb564d10e734737b,
    },
    Known {
        exercise: "hemisphere_flip",
        words: "flipped when w . n > 0: every direction sent to the wrong side",
        fingerprint: 0x5f7c61f86b5ba71d,
    },
    Known {
        exercise: "hemisphere_flip",
        words: "(w.x, w.y, |w.z|): the side tested on z, right only for n = +z",
        fingerprint: 0x96cf1da162173ae7,
    },
    Known {
        exercise: "hemisphere_flip",
        words: "n flipped to w's side: w and n swapped",
        fingerprint: 0x1268ef094ca4a3d9,
    },
    Known {
        exercise: "hemisphere_flip",
        words: "w - (w . n) n below: the factor 2 of the reflection left out (a projection, not a unit vector)",
        fingerprint: 0x1538efd80214d0ad,
    },
    Known {
        exercise: "disc_polar",
        words: "r = u1: the radius without its square root (the radial CDF r^2 forgotten)",
        fingerprint: 0x110bcc7ef1509754,
    },
    Known {
        exercise: "disc_polar",
        words: "phi = pi u2: half the turn (pi where 2 pi belongs)",
        fingerprint: 0x08d46fb3b44bc189,
    },
    Known {
        exercise: "disc_polar",
        words: "r = u1^2: the radius squared where its square root belongs",
        fingerprint: 0x9bd9f789f205724b,
    },
    Known {
        exercise: "disc_polar",
        words: "r = sqrt(u2), phi = 2 pi u1: u1 and u2 swapped",
        fingerprint: 0xc6b3a3d1f84db073,
    },
    Known {
        exercise: "disc_polar",
        words: "(r cos phi, sin phi): the radius left off y",
        fingerprint: 0x13d840b6f22bd527,
    },
    Known {
        exercise: "disc_polar",
        words: "(r sin phi, r cos phi): sine and cosine swapped, a uniform disc but not the polar map (phi runs clockwise from the y axis, so the map's inverse is not the chapter's)",
        fingerprint: 0x8c729b412115a7fb,
    },
    Known {
        exercise: "disc_concentric",
        words: "phi = (pi/2) a.y / a.x in the first wedge: pi/2 where pi/4 belongs (the disc folded over itself)",
        fingerprint: 0x2b2a98290fa8ba1f,
    },
    Known {
        exercise: "disc_concentric",
        words: "(a.y cos psi, a.y sin psi) in the second wedge: psi where pi/2 - psi belongs",
        fingerprint: 0xbd5b4da394119c87,
    },
    Known {
        exercise: "disc_concentric",
        words: "a = u: the square not mapped to [-1, 1]^2 (2u - 1 left out)",
        fingerprint: 0xf1bf4cfde1518557,
    },
    Known {
        exercise: "disc_concentric",
        words: "r = sqrt(|a|): the polar map's square root taken over",
        fingerprint: 0x2c34f0863f6e117b,
    },
    Known {
        exercise: "disc_concentric",
        words: "|a.y| > |a.x| for the first wedge: each wedge's formula used in the other",
        fingerprint: 0x28bbec01db529fe7,
    },
    Known {
        exercise: "disc_concentric",
        words: "u1 and u2 swapped: a uniform disc, but the map mirrored about the diagonal (its inverse is not the chapter's)",
        fingerprint: 0xe3f7d5629ec8ab57,
    },
    Known {
        exercise: "disc_concentric",
        words: "no case for the centre a = 0: psi = 0 / 0, a NaN point at u = (1/2, 1/2)",
        fingerprint: 0xfc6167f81760a387,
    },
    Known {
        exercise: "cosine_malley",
        words: "a uniform hemisphere direction: the cosine weighting left out",
        fingerprint: 0xf5b66f14cc986a79,
    },
    Known {
        exercise: "cosine_malley",
        words: "z = 1 - r^2: the lift without its square root",
        fingerprint: 0x9ecb7eed77f09d29,
    },
    Known {
        exercise: "cosine_malley",
        words: "1 - r = 2 min(u1, u2): the distance to the rim without the sides 1 - u1, 1 - u2",
        fingerprint: 0x0b6455c1f07a2407,
    },
    Known {
        exercise: "cosine_malley",
        words: "1 - r = min(u1, 1 - u1, u2, 1 - u2): the distance to the rim without its 2",
        fingerprint: 0x14f297906626881d,
    },
    Known {
        exercise: "cosine_malley",
        words: "z = sqrt(1 - r): the factor 1 + r of 1 - r^2 left out",
        fingerprint: 0xfae5f9333ac1375b,
    },
    Known {
        exercise: "cosine_pdf",
        words: "cos theta: the 1 / pi left out",
        fingerprint: 0xa51da13ab46f475b,
    },
    Known {
        exercise: "cosine_pdf",
        words: "cos theta / (2 pi): 2 pi where pi belongs",
        fingerprint: 0x93b9e168b91dfcb3,
    },
    Known {
        exercise: "cosine_pdf",
        words: "cos^2 theta / pi: the cosine squared",
        fingerprint: 0xa5dc6ac57b496247,
    },
    Known {
        exercise: "cosine_pdf",
        words: "|cos theta| / pi: the lower hemisphere given a density too",
        fingerprint: 0xc82a29913db71235,
    },
    Known {
        exercise: "cosine_pdf",
        words: "sin theta cos theta / pi: the density per d theta d phi, not per steradian",
        fingerprint: 0x08649ef27a84a30f,
    },
    Known {
        exercise: "Piecewise1D::sample",
        words: "the textbook search, the first bin with cdf[i + 1] >= u: at a plateau's level it lands in the bin of zero mass before it",
        fingerprint: 0x154efbc9bf4ff1bb,
    },
    Known {
        exercise: "Piecewise1D::sample",
        words: "bin floor(u n): every bin given the same mass",
        fingerprint: 0x91b6804b2177a883,
    },
    Known {
        exercise: "Piecewise1D::sample",
        words: "pdf = the bin's probability v_i w_i / I: the bin width not divided out",
        fingerprint: 0x7bc44214297f4940,
    },
    Known {
        exercise: "Piecewise1D::sample",
        words: "x = x_i + u (x_i+1 - x_i): the position within the bin from u itself, (u - c_i) / (c_i+1 - c_i) left out",
        fingerprint: 0x5434dc999ffe0c07,
    },
    Known {
        exercise: "Piecewise1D::sample",
        words: "t = (c_i+1 - u) / (c_i+1 - c_i): c_i and c_i+1 swapped, each bin run backwards",
        fingerprint: 0x6aa7c36a52eca14b,
    },
    Known {
        exercise: "PiecewiseLinear1D::sample",
        words: "uniform within the segment: the quadratic's inverse left out (the table sampled as piecewise constant)",
        fingerprint: 0xa7a5208db7c4c6e6,
    },
    Known {
        exercise: "PiecewiseLinear1D::sample",
        words: "t = sqrt(s): the inverse of a ramp from 0, right only when a = 0",
        fingerprint: 0xb37472e7a91064a1,
    },
    Known {
        exercise: "PiecewiseLinear1D::sample",
        words: "segment_inverse(b, a, s): the segment's two end densities swapped",
        fingerprint: 0x37cdda166196482b,
    },
    Known {
        exercise: "PiecewiseLinear1D::sample",
        words: "no step away from a zero-valued end: x at a knot of density 0 (pdf 0)",
        fingerprint: 0x674bd058329aa109,
    },
    Known {
        exercise: "PiecewiseLinear1D::sample",
        words: "pdf = the segment's mean density (its probability over its width): the slope left out",
        fingerprint: 0x306a2c1ae9f546c0,
    },
    Known {
        exercise: "reflect",
        words: "w_o = 2n + w_i: the source notes' mirror, right only at normal incidence (the factor cos theta_i dropped, |w_o| = sqrt(5 - 4 cos theta_i))",
        fingerprint: 0xa692da03420fc7d3,
    },
    Known {
        exercise: "reflect",
        words: "w_o = 2 (w_i . n) n - w_i: the formula of the other convention (w_i towards the light) used with w_i travelling towards the surface, so the mirror direction comes out reversed, into the surface",
        fingerprint: 0xa79f4cce210ccc07,
    },
    Known {
        exercise: "reflect",
        words: "w_o = w_i - (w_i . n) n: 1 where 2 belongs, the incident direction projected onto the surface instead of mirrored",
        fingerprint: 0xb1c0e3f818984ed3,
    },
    Known {
        exercise: "reflect",
        words: "w_o = w_i - 2n: the dot product w_i . n left out of the normal component",
        fingerprint: 0x1a165982365732eb,
    },
    Known {
        exercise: "reflect",
        words: "w_o = w_i - 2 |w_i . n| n: the cosine folded with abs() but the normal not flipped, right only when n faces away from the light",
        fingerprint: 0xc527c34b0e993ae5,
    },
    Known {
        exercise: "refract",
        words: "the normal taken as given (the source notes' outward normal assumption): a ray leaving the glass, n facing away from the light, refracts the wrong way",
        fingerprint: 0x744deb2b1c75bca9,
    },
    Known {
        exercise: "refract",
        words: "no total-internal-reflection test: past the critical angle the square root of a negative number, a NaN direction returned as transmitted",
        fingerprint: 0xb73b1d4dc50e9cb7,
    },
    Known {
        exercise: "refract",
        words: "cos_t^2 used where cos_t belongs: the square root forgotten",
        fingerprint: 0x5b8b585e7ffc6e9d,
    },
    Known {
        exercise: "refract",
        words: "eta = n2 / n1: the ratio of indices upside down (refraction bends the wrong way, total reflection entering the denser medium)",
        fingerprint: 0x047762473f2cc56b,
    },
    Known {
        exercise: "refract",
        words: "w_t = w_i + (eta cos_i - cos_t) m: the factor eta left off w_i",
        fingerprint: 0x5608f2e84fb2a09f,
    },
    Known {
        exercise: "refract",
        words: "cos_i = |w_i . n| but the normal not flipped with it: right only when n faces the light",
        fingerprint: 0x338b7684755f0bd7,
    },
    Known {
        exercise: "amplitudes",
        words: "the source notes' equations as written: cos_t = sqrt(1 - eta^2 sin^2) with no total-internal-reflection case (NaN past the critical angle) and no matched-indices case (0/0 at grazing incidence)",
        fingerprint: 0x0cbe270b4ab4b19e,
    },
    Known {
        exercise: "amplitudes",
        words: "r_p with n1 and n2 paired as in r_s, so r_p = r_s: no Brewster angle, the s reflectance for all light",
        fingerprint: 0x490b28ddd62065bd,
    },
    Known {
        exercise: "amplitudes",
        words: "cos_t from eta = n2 / n1: Snell's ratio upside down (total reflection entering the denser medium, none leaving it)",
        fingerprint: 0x7aa5b40e95ba90d4,
    },
    Known {
        exercise: "amplitudes",
        words: "cos_t = 1 - eta^2 sin^2 theta_i: the square root forgotten",
        fingerprint: 0x6c3704560884c0cc,
    },
    Known {
        exercise: "amplitudes",
        words: "r_s = (n1 cos_i - cos_t) / (n1 cos_i + cos_t): the index n2 left off the s terms",
        fingerprint: 0x2e68916d89a2925e,
    },
    Known {
        exercise: "amplitudes",
        words: "cos_i used as given: a negative cosine (the light on the normal's other side) not folded with abs(), so |r| > 1",
        fingerprint: 0xccf3115fe4f9d73d,
    },
    Known {
        exercise: "fresnel_transmittance",
        words: "T = t^2: the beam factor (n2 cos_t) / (n1 cos_i) forgotten (1 - R = 0.96 but t_s^2 = 0.64 at normal incidence on glass)",
        fingerprint: 0x64aa2098acee8e47,
    },
    Known {
        exercise: "fresnel_transmittance",
        words: "T = (n1 cos_i) / (n2 cos_t) t^2: the beam factor upside down",
        fingerprint: 0x71c31b71c400a0df,
    },
    Known {
        exercise: "fresnel_transmittance",
        words: "T_s = 4ab / (a + b): the denominator's square forgotten",
        fingerprint: 0x17b3c69426ab93f6,
    },
    Known {
        exercise: "fresnel_transmittance",
        words: "T_s = 2ab / (a + b)^2: 2 where 4 belongs",
        fingerprint: 0x19b1b89d0ffc91ac,
    },
    Known {
        exercise: "fresnel_transmittance",
        words: "T = 1 past the critical angle: the total-internal-reflection case returns the matched-indices answer (nothing is transmitted there)",
        fingerprint: 0x22f81c1b3898b08a,
    },
    Known {
        exercise: "fresnel_transmittance",
        words: "no matched-indices case: at grazing incidence with n1 = n2 both cosines are 0 and T = 0 where it is 1",
        fingerprint: 0x21778c3dda4347d2,
    },
    Known {
        exercise: "schlick",
        words: "R0 + (1 - R0)(1 - cos)^4: the fourth power where Schlick has the fifth (every claim of a reflectance kept, only the formula tells)",
        fingerprint: 0x3cf219ddc40a1944,
    },
    Known {
        exercise: "schlick",
        words: "the source notes' Schlick, always with cos theta_i: inside the denser medium the wrong cosine, and no total internal reflection",
        fingerprint: 0x926b5f9446e4f696,
    },
    Known {
        exercise: "schlick",
        words: "R0 = ((n1 - 1)/(n1 + 1))^2: the second medium taken to be air",
        fingerprint: 0x9ba72240d7a06053,
    },
    Known {
        exercise: "schlick",
        words: "R0 + (1 - cos)^5: the factor (1 - R0) left out (R > 1 at grazing incidence)",
        fingerprint: 0xdd48c7077ceb481b,
    },
    Known {
        exercise: "schlick",
        words: "the cosine on the denser side: cos_t entering the denser medium and cos_i leaving it (the test n1 <= n2 the wrong way round)",
        fingerprint: 0xa40e36660d54b84b,
    },
    Known {
        exercise: "schlick",
        words: "cos_t computed with n1 and n2 swapped: inside the denser medium never a total internal reflection, and the wrong cosine",
        fingerprint: 0x3264e05bb15c8134,
    },
    Known {
        exercise: "schlick",
        words: "R = 0 past the critical angle: the total-internal-reflection branch returns nothing reflected",
        fingerprint: 0x270803de4fbf3eda,
    },
    Known {
        exercise: "narrow_lobe_brdf",
        words: "rho lobe(w_i): the lobe without its 1 / |cos theta_i| (the mirror that keeps the cosine, the chapter's planted bug)",
        fingerprint: 0x7d79b6724b0f7414,
    },
    Known {
        exercise: "narrow_lobe_brdf",
        words: "rho lobe(w_i) / cos^2 theta_i: the cosine divided out twice",
        fingerprint: 0xd841457f7725efc4,
    },
    Known {
        exercise: "narrow_lobe_brdf",
        words: "lobe(w_i) / cos theta_i: the albedo rho left out",
        fingerprint: 0x5d70c30cb8c1dc8b,
    },
    Known {
        exercise: "narrow_lobe_brdf",
        words: "rho lobe(w_i) / (pi cos theta_i): Lambert's 1 / pi carried over to the mirror",
        fingerprint: 0x16630c3fa8914c1b,
    },
    Known {
        exercise: "narrow_lobe_brdf",
        words: "rho lobe(w_i) / |cos theta_i| below the surface too: the case w_i.z <= 0 left out",
        fingerprint: 0x6960e14a03a2573b,
    },
    Known {
        exercise: "narrow_lobe_brdf",
        words: "the surface test w_i.z < 0 where <= 0 belongs: on the surface it divides by a cosine of 0 and returns infinity (a NaN sample in the renderer)",
        fingerprint: 0xca9f2229214ffbe1,
    },
    Known {
        exercise: "Sellmeier::index",
        words: "lambda squared in nm while C is in um^2: every term about B, n flat at about sqrt(1 + sum B)",
        fingerprint: 0xb2b2a288a35cf8c8,
    },
    Known {
        exercise: "Sellmeier::index",
        words: "returns n^2: the square root forgotten",
        fingerprint: 0xdaca0c51b425e44e,
    },
    Known {
        exercise: "Sellmeier::index",
        words: "B lambda / (lambda - C): lambda where lambda^2 belongs",
        fingerprint: 0xd7981281255d0d6a,
    },
    Known {
        exercise: "Sellmeier::index",
        words: "lambda^2 = nm^2 / 1000: the conversion to um applied once, not squared",
        fingerprint: 0xd4a132cb5982251c,
    },
    Known {
        exercise: "Sellmeier::index",
        words: "C lambda^2 / (lambda^2 - B): B and C swapped in each term",
        fingerprint: 0x0b67fcfc60e324e3,
    },
    Known {
        exercise: "Sellmeier::index",
        words: "n^2 = sum B lambda^2 / (lambda^2 - C): the 1 (the vacuum's n^2) left out",
        fingerprint: 0x4cc85f0051c2bc6a,
    },
    Known {
        exercise: "airy_r",
        words: "the source notes' denominator 1 - r12 r23 e^(2 i delta): the sign of r21 = -r12 lost",
        fingerprint: 0xa5e8c81af2a11788,
    },
    Known {
        exercise: "airy_r",
        words: "e^(i delta) where the round trip needs e^(2 i delta): one crossing's phase",
        fingerprint: 0x33ed1b5362e475b9,
    },
    Known {
        exercise: "airy_r",
        words: "(r23 + r12 z) / (1 + r12 r23 z): r12 and r23 swapped in the numerator",
        fingerprint: 0x5f3217561e39a20d,
    },
    Known {
        exercise: "airy_r",
        words: "r12 + r23 z / (1 + r12 r23 z): the factor t12 t21 = 1 - r12^2 of the multiply reflected waves left out",
        fingerprint: 0x3923ba7f5ce73cff,
    },
    Known {
        exercise: "airy_r",
        words: "r12 + r23 z: two waves, the multiple reflections' denominator left out",
        fingerprint: 0xa2c1abf60098eecb,
    },
    Known {
        exercise: "airy_r",
        words: "z = e^(-2 i delta): the phase's other sign, which for an evanescent film (complex delta) grows instead of decaying",
        fingerprint: 0xb96e4a6b83e95172,
    },
    Known {
        exercise: "lambert_brdf",
        words: "f = rho: the albedo taken for the BRDF's value, without the 1/pi (its albedo is pi rho)",
        fingerprint: 0x98a27b022e9ba8a8,
    },
    Known {
        exercise: "lambert_brdf",
        words: "f = rho / (2 pi): the uniform hemisphere's density 1/(2 pi) where 1/pi belongs (its albedo is rho / 2)",
        fingerprint: 0x4987935f4e7c4e5c,
    },
    Known {
        exercise: "lambert_brdf",
        words: "f = rho cos(theta_i) / pi: the cosine of the rendering equation folded into the BRDF (not reciprocal, albedo 2 rho / 3)",
        fingerprint: 0x9eb03ad803b68300,
    },
    Known {
        exercise: "lambert_brdf",
        words: "f = 1 / pi: rho left out (every surface white)",
        fingerprint: 0x0137b1abb987537d,
    },
    Known {
        exercise: "lambert_brdf",
        words: "only w_i tested against the surface: light reflected to directions below it (not reciprocal)",
        fingerprint: 0xc78b0ae242e7f6e9,
    },
    Known {
        exercise: "lambert_brdf",
        words: "rho / pi for every pair of directions: the test for directions below the surface left out",
        fingerprint: 0xfcc8963b6bc01a21,
    },
    Known {
        exercise: "roulette",
        words: "a survivor keeps f, not f / p: the estimate shrinks to p f (the image darkens)",
        fingerprint: 0xc66044f7fef236b3,
    },
    Known {
        exercise: "roulette",
        words: "survives when u <= p (the source notes' rule): p = 0 and u = 0 survive and give 0 / 0",
        fingerprint: 0xbd3acce999f1c7e8,
    },
    Known {
        exercise: "roulette",
        words: "survives when u > p: the threshold on the wrong side (right on average only for p = 1/2)",
        fingerprint: 0x5db517ad6509f7e7,
    },
    Known {
        exercise: "roulette",
        words: "a survivor carries f / (1 - p): divided by the probability of being killed",
        fingerprint: 0x898e853c854ea53f,
    },
    Known {
        exercise: "roulette",
        words: "p read as the probability of termination: survives when u >= p and carries f / (1 - p) (unbiased, but p = 0 always survives and p = 1 never does)",
        fingerprint: 0xfe0816cc8c976ef3,
    },
    Known {
        exercise: "roulette",
        words: "a survivor carries f p: p to the power 1 where -1 belongs",
        fingerprint: 0x584960e20a60e0f3,
    },
    Known {
        exercise: "roulette",
        words: "a survivor carries f / u: divided by the random number instead of the probability",
        fingerprint: 0x2b957afb11d53bd0,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "p_A r^2: the light's cosine left out (the density no longer grows as the light turns edge-on)",
        fingerprint: 0x7bf6182a928ba659,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "p_A / |cos|: the distance squared left out",
        fingerprint: 0xd93627ba4d7a207f,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "p_A r^2 / cos without the absolute value (the source notes' formula): negative for a light facing the point",
        fingerprint: 0x76f969721f3f69bb,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "r^2 / |cos|: the area density left out (taken as 1)",
        fingerprint: 0x860cbe2da69a1ead,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "p_A r / |cos|: the distance where its square belongs",
        fingerprint: 0xb38aa0323a861ca2,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "p_A r^2 / cos^2: the cosine squared",
        fingerprint: 0x781f2f409830506d,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "p_A |cos| / r^2: the conversion the wrong way round (solid angle to area)",
        fingerprint: 0x9b61f4f483f543dd,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "no case for a light seen edge-on: cos = 0 gives infinity instead of 0",
        fingerprint: 0x0bfac4bce20aeedd,
    },
    Known {
        exercise: "area_to_solid_angle",
        words: "0 when cos <= 0, as if the light faced away: but a light facing the point has n . w < 0",
        fingerprint: 0x7af3c4fa11c48ab5,
    },
    Known {
        exercise: "hero_uniform",
        words: "lanes rotated without the mod 1: the lanes past 830 nm leave the range (the estimate too dark)",
        fingerprint: 0x928147dd447362dc,
    },
    Known {
        exercise: "hero_uniform",
        words: "each lane weighted by 1 / (N x 470), as if the lanes shared one density: the lanes summed, not averaged (N times too bright)",
        fingerprint: 0xa6bda6506139df7d,
    },
    Known {
        exercise: "hero_uniform",
        words: "the source notes' band: a random wavelength in 380-780 nm and its neighbours 5 nm apart, not lanes spread over the range",
        fingerprint: 0xdc4b5dcd132a735f,
    },
    Known {
        exercise: "hero_uniform",
        words: "the lanes rotated over 380-780 nm with density 1/400: the constants of another visible range",
        fingerprint: 0x05eb2bfd024f7a41,
    },
    Known {
        exercise: "hero_uniform",
        words: "each lane weighted by 470, the range, where its reciprocal 1/470 belongs",
        fingerprint: 0x02ad9301615808dc,
    },
    Known {
        exercise: "hero_uniform",
        words: "hero_pdf left at 0: the hero's own density missing (the hero weighted by nothing once the other lanes terminate)",
        fingerprint: 0xd0440b3eff93d8f8,
    },
    Known {
        exercise: "hero_uniform",
        words: "the wrap applied to the wavelength itself (mod 470 nm) instead of to its offset from 360 nm: lanes below 360 nm",
        fingerprint: 0x3ec0e7ab582df8fb,
    },
    Known {
        exercise: "srgb_encode",
        words: "x^(1/2.2): the source notes' pure power law, not the sRGB curve",
        fingerprint: 0xa782cd50e0c2ddef,
    },
    Known {
        exercise: "srgb_encode",
        words: "x^2.2: the gamma applied the wrong way (linear 0.5 becomes code 55, not 188)",
        fingerprint: 0x719cf56b9509960c,
    },
    Known {
        exercise: "srgb_encode",
        words: "1.055 x^2.4 - 0.055: the power 2.4 where 1/2.4 belongs (the decoding's exponent)",
        fingerprint: 0x83e8b5618828c222,
    },
    Known {
        exercise: "srgb_encode",
        words: "the breakpoint 0.04045 (the decoding's, an encoded value) on the linear side: the straight segment thirteen times too long",
        fingerprint: 0x6e641b2279f8a131,
    },
    Known {
        exercise: "srgb_encode",
        words: "1.055 x^(1/2.4) without the offset - 0.055: above 1 at x = 1",
        fingerprint: 0x5f3802d5846d2ed3,
    },
    Known {
        exercise: "srgb_encode",
        words: "x / 12.92 near black: the decoding's straight segment",
        fingerprint: 0xb066e8c7f9195ea4,
    },
    Known {
        exercise: "srgb_encode",
        words: "x >= 0.0031308 on the power segment: the breakpoint itself encoded by the power (the standard puts it on the straight segment)",
        fingerprint: 0xcd0f79846ad663de,
    },
    Known {
        exercise: "srgb_encode",
        words: "12.92 x for everything below the breakpoint: negative inputs not clamped to 0 (and NaN kept)",
        fingerprint: 0x68b9c6ffb77505de,
    },
    Known {
        exercise: "srgb_decode",
        words: "V^2.2: the source notes' pure power law, not the sRGB curve",
        fingerprint: 0x856bce1347190794,
    },
    Known {
        exercise: "srgb_decode",
        words: "V^(1/2.2): the gamma applied the wrong way (the encoding's direction)",
        fingerprint: 0x66b058ac50189f28,
    },
    Known {
        exercise: "srgb_decode",
        words: "((V + 0.055) / 1.055)^(1/2.4): the power 1/2.4 where 2.4 belongs (the encoding's exponent)",
        fingerprint: 0xec09c055792c9ce1,
    },
    Known {
        exercise: "srgb_decode",
        words: "the breakpoint 0.0031308 (the encoding's, a linear value) on the encoded side: the power used down to near black",
        fingerprint: 0xa359a82262655281,
    },
    Known {
        exercise: "srgb_decode",
        words: "(V / 1.055)^2.4: the offset + 0.055 left out",
        fingerprint: 0xa9f9ed3de2441030,
    },
    Known {
        exercise: "srgb_decode",
        words: "12.92 V near black: the encoding's straight segment",
        fingerprint: 0xdf09c8826f9b8583,
    },
    Known {
        exercise: "srgb_decode",
        words: "V >= 0.04045 on the power segment: the breakpoint itself decoded by the power (the standard puts it on the straight segment)",
        fingerprint: 0x8bd5c58454e3021e,
    },
    Known {
        exercise: "srgb_decode",
        words: "V / 12.92 for everything below the breakpoint: negative inputs not clamped to 0 (and NaN kept)",
        fingerprint: 0x194e608de4ec306e,
    },
];
