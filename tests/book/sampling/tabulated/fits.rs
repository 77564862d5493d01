//! The project's code fits every table.

use super::*;

#[test]
fn constant_fits_smooth_table() {
    let t = smooth();
    let d = t.constant();
    assert_fits(&t, false, &draw(1, N, |u| d.sample(u).x));
}

#[test]
fn constant_fits_spiky_table() {
    let t = spiky();
    let d = t.constant();
    assert_fits(&t, false, &draw(2, N, |u| d.sample(u).x));
}

#[test]
fn constant_fits_table_with_zero_bins() {
    let t = with_zeros();
    let d = t.constant();
    assert_fits(&t, false, &draw(3, N, |u| d.sample(u).x));
}

#[test]
fn constant_fits_single_bin() {
    let t = single_bin();
    let d = t.constant();
    let xs = draw(4, N, |u| d.sample(u).x);
    assert!(xs.iter().all(|&x| (2.0..3.5).contains(&x)));
    assert_fits(&t, false, &xs);
}

#[test]
fn linear_fits_every_table() {
    let mut tables = linear_tables();
    tables.push(triangle());
    for (k, t) in tables.iter().enumerate() {
        let d = t.linear();
        assert_fits(t, true, &draw(10 + k as u64, N, |u| d.sample(u).x));
    }
}
