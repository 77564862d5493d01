//! The image format.

use super::*;
use raylemma::image::png::{encode_grey_png, encode_png};

/// `decoded` is `t / max t` at every whole nanometre of 380-830 within half a pixel.
fn quantisation_problem(t: &Table, decoded: &Table, height: u32) -> Option<String> {
    let max = image_wavelengths()
        .iter()
        .map(|&l| t.eval(l))
        .fold(0.0, f64::max);
    let bound = 0.5 / f64::from(height) + 1e-12;
    image_wavelengths().iter().find_map(|&l| {
        let (want, got) = (t.eval(l) / max, decoded.eval(l));
        ((got - want).abs() > bound).then(|| format!("{l} nm: {got} vs {want}"))
    })
}

#[test]
fn image_round_trip_within_half_a_pixel() {
    for l in lamps() {
        for height in [1, 100, IMAGE_HEIGHT] {
            let png = write_image(&l.spectrum, height).unwrap();
            let back = parse_image(&png, l.stem).unwrap();
            assert_eq!(back.wavelengths(), image_wavelengths().as_slice());
            if let Some(e) = quantisation_problem(&l.spectrum, &back, height) {
                panic!("{} at height {height}: {e}", l.name);
            }
        }
    }
}

/// The drawings shipped in `data/` still decode to their tables (set
/// `RAYLEMMA_WRITE_DATA=1` to redraw them from the tables first).
#[test]
fn shipped_images_match_their_tables() {
    if std::env::var_os("RAYLEMMA_WRITE_DATA").is_some() {
        write_lamp_images(&data_dir()).unwrap();
    }
    for l in lamps() {
        let path = data_dir().join(format!("{}.png", l.stem));
        let back = load_image(&path).unwrap_or_else(|e| panic!("{e}"));
        if let Some(e) = quantisation_problem(&l.spectrum, &back, IMAGE_HEIGHT) {
            panic!("{}: {e}", path.display());
        }
    }
}

fn png_gray(width: u32, height: u32, pixel: impl Fn(u32, u32) -> u8) -> Vec<u8> {
    let grey: Vec<u8> = (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| pixel(x, y))
        .collect();
    encode_grey_png(width, height, &grey).unwrap()
}

/// A PNG of any colour type and bit depth, written by the `png` crate itself.
fn png_of(
    width: u32,
    height: u32,
    color: png::ColorType,
    depth: png::BitDepth,
    palette: Option<Vec<u8>>,
    data: &[u8],
) -> Vec<u8> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(color);
    encoder.set_depth(depth);
    if let Some(p) = palette {
        encoder.set_palette(p);
    }
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(data).unwrap();
    writer.finish().unwrap();
    out
}

/// The value of a column is the share of dark pixels wherever they are; 127 is dark,
/// 128 is not; colour images are read by their luma. A fully dark column is 1, not the
/// infinite "ratio of black pixels to white pixels" of the source read literally.
#[test]
fn image_columns_are_shares_of_dark_pixels() {
    let png = png_gray(IMAGE_WIDTH, 10, |x, y| match x {
        0 => 0,
        1 if y % 2 == 0 => 127,
        2 if y < 3 => 128,
        3 if y == 9 => 10,
        _ => 255,
    });
    let t = parse_image(&png, "columns.png").unwrap();
    assert_eq!(&t.values()[..5], &[1.0, 0.5, 0.0, 0.1, 0.0]);
    assert_eq!(t.eval(380.5), 0.75);

    // Dark red, luma (2126 * 200 + 7152 * 10 + 722 * 10) / 10000 = 50, in one column below
    // the first row; elsewhere pale yellow, luma (2126 * 250 + 7152 * 250 + 722 * 120) /
    // 10000 = 240.
    let pixel = |x: u32, y: u32| {
        if x == 200 && y > 0 {
            [200u8, 10, 10]
        } else {
            [250, 250, 120]
        }
    };
    let rgb: Vec<u8> = (0..4)
        .flat_map(|y| (0..IMAGE_WIDTH).flat_map(move |x| pixel(x, y)))
        .collect();
    let t = parse_image(&encode_png(IMAGE_WIDTH, 4, &rgb).unwrap(), "rgb.png").unwrap();
    assert_eq!(t.eval(580.0), 0.75);
    assert_eq!(t.values().iter().filter(|&&v| v > 0.0).count(), 1);

    // The same picture as 16-bit RGBA (alpha ignored; a channel's high byte is its 8-bit
    // value) and as a palette of two colours: the same curve.
    let rgba16: Vec<u8> = (0..4)
        .flat_map(|y| (0..IMAGE_WIDTH).flat_map(move |x| pixel(x, y)))
        .collect::<Vec<u8>>()
        .chunks_exact(3)
        .flat_map(|p| [p[0], 7, p[1], 7, p[2], 7, 0, 0])
        .collect();
    let png16 = png_of(
        IMAGE_WIDTH,
        4,
        png::ColorType::Rgba,
        png::BitDepth::Sixteen,
        None,
        &rgba16,
    );
    assert_eq!(
        parse_image(&png16, "rgba16.png").unwrap().values(),
        t.values()
    );
    let indices: Vec<u8> = (0..4)
        .flat_map(|y| (0..IMAGE_WIDTH).map(move |x| u8::from(x == 200 && y > 0)))
        .collect();
    let palette = Some(vec![250, 250, 120, 200, 10, 10]);
    let indexed = png_of(
        IMAGE_WIDTH,
        4,
        png::ColorType::Indexed,
        png::BitDepth::Eight,
        palette,
        &indices,
    );
    assert_eq!(
        parse_image(&indexed, "palette.png").unwrap().values(),
        t.values()
    );
}

#[test]
fn bad_images_are_refused_with_file_and_reason() {
    let e = parse_image(
        &png_gray(450, 20, |_, y| if y > 10 { 0 } else { 255 }),
        "seed.png",
    )
    .unwrap_err();
    assert_eq!((e.file.as_str(), e.line), ("seed.png", 0));
    assert!(
        e.problem.contains("450 pixels wide") && e.problem.contains("451"),
        "{e}"
    );
    let e = parse_image(&png_gray(452, 20, |_, _| 0), "wide.png").unwrap_err();
    assert!(
        e.to_string().starts_with("wide.png: the image is 452"),
        "{e}"
    );
    let e = parse_image(&png_gray(IMAGE_WIDTH, 20, |_, _| 200), "blank.png").unwrap_err();
    assert!(e.problem.contains("the curve is empty"), "{e}");
    let e = parse_image(b"wavelength_nm,value\n380,1\n", "table.csv").unwrap_err();
    assert!(
        e.file == "table.csv" && e.problem.contains("cannot decode"),
        "{e}"
    );
    let e = parse_image(&[], "empty.png").unwrap_err();
    assert!(e.problem.contains("cannot decode"), "{e}");
    let e = load_image(&data_dir().join("no_such_lamp.png")).unwrap_err();
    assert!(
        e.file.ends_with("no_such_lamp.png") && e.problem.contains("cannot read"),
        "{e}"
    );
    let zero = Table::new(vec![300.0, 370.0], vec![1.0, 1.0]).unwrap();
    assert!(write_image(&zero, 10).is_err());
    assert!(write_image(&amber_led_table(), 0).is_err());
}

/// An image's size is judged from its header before a pixel is decoded: the crafted
/// 78-byte files of `tests/data/png/` (made by its `make.py`) claim 451 x 10^9,
/// 451 x 300000 and 451 x 4097 pixels and are refused with the height; the tallest image
/// read, 451 x `IMAGE_MAX_HEIGHT`, is read. (Before, the whole image was decoded first,
/// within the `image` crate's default limit of 512 MB: 451 x 300000 grey cost 135 MB,
/// and CI's fuzzer drove the tables target past its 100 MB limit.)
#[test]
fn an_image_taller_than_read_is_refused_before_decoding() {
    let crafted = crate::support::root().join("tests/data/png");
    for (name, height) in [
        ("tall-451x1000000000.png", "1000000000"),
        ("tall-451x300000.png", "300000"),
        ("tall-451x4097.png", "4097"),
    ] {
        let e = load_image(&crafted.join(name)).unwrap_err();
        assert!(
            e.file.ends_with(name)
                && e.problem
                    .starts_with(&format!("the image is {height} pixels tall; at most 4096")),
            "{e}"
        );
    }
    let tallest = png_gray(
        IMAGE_WIDTH,
        IMAGE_MAX_HEIGHT,
        |x, _| if x == 7 { 0 } else { 255 },
    );
    let t = parse_image(&tallest, "tallest.png").unwrap();
    assert_eq!(t.values().iter().filter(|&&v| v == 1.0).count(), 1);
}

/// A drawing samples like the table it was drawn from, up to its quantisation: the
/// sampler built from the shipped amber LED image has the same luminance estimate (its
/// own Y, computed exactly) as the sampler built from the table, within 1 %.
#[test]
fn a_drawing_is_a_usable_light() {
    let drawn = load_image(&data_dir().join("lamp_amber_led.png")).unwrap();
    let s = sampler(&drawn);
    for u in [0.0, 0.25, 0.5, ONE_MINUS_EPSILON] {
        if let Some(e) = unsound(&drawn, &s, u) {
            panic!("{e}");
        }
    }
    let table = amber_led_table();
    let ratio = |t: &Table| y_of(t) / t.integral();
    assert!((ratio(&drawn) / ratio(&table) - 1.0).abs() < 0.01);
}
