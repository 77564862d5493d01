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
];
