//! What the hand-out knows of each typical mistake (see [`super`]): its words and the
//! fingerprint of its twin's probe. Written by the chapter's tests from the twins
//! (`RAYLEMMA_WRITE_KNOWN=1 cargo test --test book coursework::mistakes`); do not edit.

use super::Known;

/// Every typical mistake, in the book's order.
pub const KNOWN: &[Known] = &[
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
];
