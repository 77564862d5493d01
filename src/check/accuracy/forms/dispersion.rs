//! The forms answering `data/corpus/dispersion.txt`: [`crate::optics::dispersion`], the
//! Sellmeier index and the Abbe number of the embedded fits (one verb per material).

use crate::check::accuracy::{Answer, Form};
use crate::optics::dispersion::{FUSED_SILICA, N_BK7, Sellmeier, WATER, material};

/// `n`, or no answer where the crate's index is NaN (`n² < 0`).
fn answer(n: f64) -> Answer {
    (!n.is_nan()).then(|| vec![n])
}

fn index_bk7(a: &[f64]) -> Answer {
    answer(material(N_BK7).index(a[0]))
}

fn index_silica(a: &[f64]) -> Answer {
    answer(material(FUSED_SILICA).index(a[0]))
}

fn index_water(a: &[f64]) -> Answer {
    answer(material(WATER).index(a[0]))
}

/// [`Sellmeier::abbe_at`] (what [`Sellmeier::abbe`] is at the d, F and C lines: the
/// corpus's first Abbe case).
fn abbe(glass: &Sellmeier, a: &[f64]) -> Answer {
    answer(glass.abbe_at(a[0], a[1], a[2]))
}

/// The textbook index: each term as `B λ² / (λ² − C)` (the crate's before it divided λ²
/// out; NaN where λ² overflows).
fn textbook_index(glass: &Sellmeier, nm: f64) -> f64 {
    let lsq = (nm * 1e-3).powi(2);
    let sum: f64 = glass
        .terms
        .iter()
        .map(|&(bi, ci)| bi * lsq / (lsq - ci))
        .sum();
    (1.0 + sum).sqrt()
}

/// The textbook Abbe number: the difference of two rounded indices (the crate's before
/// [`Sellmeier::abbe_at`]).
fn textbook_abbe(glass: &Sellmeier, a: &[f64]) -> Answer {
    let idx = |nm| textbook_index(glass, nm);
    answer((idx(a[0]) - 1.0) / (idx(a[1]) - idx(a[2])))
}

fn textbook_n_bk7(a: &[f64]) -> Answer {
    answer(textbook_index(material(N_BK7), a[0]))
}

fn textbook_n_silica(a: &[f64]) -> Answer {
    answer(textbook_index(material(FUSED_SILICA), a[0]))
}

fn textbook_n_water(a: &[f64]) -> Answer {
    answer(textbook_index(material(WATER), a[0]))
}

fn textbook_abbe_bk7(a: &[f64]) -> Answer {
    textbook_abbe(material(N_BK7), a)
}

fn textbook_abbe_silica(a: &[f64]) -> Answer {
    textbook_abbe(material(FUSED_SILICA), a)
}

fn textbook_abbe_water(a: &[f64]) -> Answer {
    textbook_abbe(material(WATER), a)
}

fn abbe_bk7(a: &[f64]) -> Answer {
    abbe(material(N_BK7), a)
}

fn abbe_silica(a: &[f64]) -> Answer {
    abbe(material(FUSED_SILICA), a)
}

fn abbe_water(a: &[f64]) -> Answer {
    abbe(material(WATER), a)
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    let t = |verb, eval| Form::stable(verb, eval).textbook();
    vec![
        f("n_bk7", index_bk7),
        t("n_bk7", textbook_n_bk7),
        f("n_silica", index_silica),
        t("n_silica", textbook_n_silica),
        f("n_water", index_water),
        t("n_water", textbook_n_water),
        f("abbe_bk7", abbe_bk7),
        t("abbe_bk7", textbook_abbe_bk7),
        f("abbe_silica", abbe_silica),
        t("abbe_silica", textbook_abbe_silica),
        f("abbe_water", abbe_water),
        t("abbe_water", textbook_abbe_water),
    ]
}
