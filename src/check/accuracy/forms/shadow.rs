//! The forms answering `data/corpus/shadow.txt`: [`crate::transport::shadow`].

use super::v3;
use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::transport::shadow::{Heuristic, SphereLight, area_to_solid_angle, triangle_solid_angle};

fn to_solid_angle(a: &[f64]) -> Answer {
    Some(vec![area_to_solid_angle(a[0], a[1], a[2])])
}

fn light(a: &[f64]) -> Option<SphereLight> {
    SphereLight::new(v3(&a[0..3]), a[3]).ok()
}

fn one_minus_cos(a: &[f64]) -> Answer {
    light(a)?.one_minus_cos_max(v3(&a[4..7])).map(|h| vec![h])
}

/// `1 - cos(theta_max)` as written, `1 - sqrt(1 - (R/d)^2)`: the subtraction the chapter
/// replaces.
fn one_minus_cos_as_written(a: &[f64]) -> Answer {
    let d = (v3(&a[4..7]) - v3(&a[0..3])).length();
    if d.is_nan() || d <= a[3] {
        return None;
    }
    let sine = a[3] / d;
    Some(vec![1.0 - (1.0 - sine * sine).sqrt()])
}

fn cone(a: &[f64]) -> Answer {
    Some(vec![light(a)?.solid_angle(v3(&a[4..7]))])
}

fn cone_as_written(a: &[f64]) -> Answer {
    let h = one_minus_cos_as_written(a).map_or(0.0, |h| h[0]);
    Some(vec![std::f64::consts::TAU * h])
}

fn balance(a: &[f64]) -> Answer {
    Some(vec![Heuristic::Balance.weight(a[0], a[1])])
}

fn power(a: &[f64]) -> Answer {
    Some(vec![Heuristic::Power.weight(a[0], a[1])])
}

/// The former weights, `a / (a + b)` of the densities or of their squares: the sum
/// overflows, the squares overflow (to a NaN weight) or underflow.
fn weight_as_written(own: f64, other: f64) -> f64 {
    if own + other > 0.0 {
        own / (own + other)
    } else {
        0.0
    }
}

fn balance_as_written(a: &[f64]) -> Answer {
    Some(vec![weight_as_written(a[0], a[1])])
}

fn power_as_written(a: &[f64]) -> Answer {
    Some(vec![weight_as_written(a[0] * a[0], a[1] * a[1])])
}

fn triangle(a: &[f64]) -> Answer {
    Some(vec![triangle_solid_angle(
        v3(&a[0..3]),
        v3(&a[3..6]),
        v3(&a[6..9]),
    )])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = |verb, form, expect, eval| Form::new(verb, form, Precision::Double, expect, eval);
    use Expect::{Exceeds, Within};
    vec![
        f("area_to_solid_angle", "stable", Within, to_solid_angle),
        f("one_minus_cos_max", "stable", Within, one_minus_cos),
        f(
            "one_minus_cos_max",
            "textbook",
            Exceeds,
            one_minus_cos_as_written,
        ),
        f("cone_solid_angle", "stable", Within, cone),
        f("cone_solid_angle", "textbook", Exceeds, cone_as_written),
        f("mis_balance", "stable", Within, balance),
        f("mis_balance", "textbook", Exceeds, balance_as_written),
        f("mis_power", "stable", Within, power),
        f("mis_power", "textbook", Exceeds, power_as_written),
        f("triangle_solid_angle", "stable", Within, triangle),
    ]
}
