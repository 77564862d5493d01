//! Random corruptions of real scenes never panic.

use super::*;

#[test]
fn random_corruptions_never_panic() {
    // A fuzzer's diet: bytes flipped, lines dropped or duplicated, the file truncated, in
    // every canonical scene. The parser must answer Ok or a DataError, never panic.
    let mut rng = rng::seeded(23);
    let texts: Vec<String> = [
        "cornell.toml",
        "bubble.toml",
        "furnace.toml",
        "dispersion.toml",
    ]
    .iter()
    .map(|n| std::fs::read_to_string(scenes_dir().join(n)).unwrap())
    .chain([GOOD.to_string()])
    .collect();
    let alphabet = b" =[]{}\",.-0123456789aeinrstxyz#\n";
    let mut refused = 0;
    for k in 0..3000 {
        let mut bytes = texts[k % texts.len()].clone().into_bytes();
        match k % 4 {
            0 => {
                for _ in 0..1 + k % 5 {
                    let i = (rng::uniform(&mut rng, 0.0, 1.0) * bytes.len() as f64) as usize;
                    let c = alphabet
                        [(rng::uniform(&mut rng, 0.0, 1.0) * alphabet.len() as f64) as usize];
                    let last = bytes.len() - 1;
                    bytes[i.min(last)] = c;
                }
            }
            1 => bytes.truncate((rng::uniform(&mut rng, 0.0, 1.0) * bytes.len() as f64) as usize),
            2 => {
                let text = String::from_utf8_lossy(&bytes).into_owned();
                let mut lines: Vec<&str> = text.lines().collect();
                let i = (rng::uniform(&mut rng, 0.0, 1.0) * lines.len() as f64) as usize;
                lines.remove(i.min(lines.len() - 1));
                bytes = lines.join("\n").into_bytes();
            }
            _ => {
                let text = String::from_utf8_lossy(&bytes).into_owned();
                let mut lines: Vec<&str> = text.lines().collect();
                let i = (rng::uniform(&mut rng, 0.0, 1.0) * lines.len() as f64) as usize;
                let l = lines[i.min(lines.len() - 1)];
                lines.insert(i.min(lines.len() - 1), l);
                bytes = lines.join("\n").into_bytes();
            }
        }
        let text = String::from_utf8_lossy(&bytes);
        let outcome =
            std::panic::catch_unwind(|| render::parse(&text, "fuzz.toml", &scenes_dir()).is_err());
        match outcome {
            Ok(true) => refused += 1,
            Ok(false) => {}
            Err(_) => panic!("the parser panicked on corruption {k}:\n{text}"),
        }
    }
    // The corruptions must actually reach the checks (a generator that left the files
    // valid would make this test pass vacuously).
    assert!(
        refused > 1000,
        "only {refused} of 3000 corruptions were refused"
    );
}
