//! The scrubber's rule (trivial lines exempt) and its refusal of a hand-out while a solution
//! line is anywhere in it.

use super::*;

#[test]
fn the_trivial_rule_exempts_lines_that_name_less_than_two_things() {
    for line in [
        "}",
        "} else {",
        "None",
        "Some(t)",
        "0.0",
        "return V3::ZERO;",
        "Wavelengths {",
        "if cos2_t < 0.0 {",
        "return Refraction::TotalInternalReflection;",
        "Ok(())",
    ] {
        assert!(scrub::is_trivial(line), "{line}");
    }
    for line in [
        "let s = u.y.cbrt();",
        "let w = n.cross(t);",
        "self.entries.iter().find(|e| e.0 == key)",
    ] {
        assert!(!scrub::is_trivial(line), "{line}");
    }
    assert_eq!(
        scrub::fragments("    let x = \"a // b\"; // the comment"),
        ["let x = \"a // b\";", "the comment"]
    );
    assert_eq!(
        scrub::names("1.5e-3 * std::f64::consts::PI + x.y"),
        ["std::consts::PI", "x", "y"]
    );
}

#[test]
fn the_hand_out_is_refused_while_a_solution_line_is_anywhere_in_it() {
    let leak = "//! fixture\nfn independent() {\n    let s = u.y.cbrt();   // copied\n}\n";
    let Err(EditionError::Leaks(leaks)) = edition::make(crate_with(leak), Kind::HandOut) else {
        panic!("a leaked line was not refused");
    };
    assert_eq!(leaks.len(), 1);
    let text = leaks[0].to_string();
    assert!(
        text.starts_with("tests/book/main.rs:3: `let s = u.y.cbrt();`"),
        "{text}"
    );
    assert!(
        text.contains("exercise `disc_polar`, at src/fixture.rs:7"),
        "{text}"
    );
    // The solutions edition keeps the solutions, so it has nothing to refuse.
    assert!(edition::make(crate_with(leak), Kind::Solutions).is_ok());
    // Without the copy, the hand-out is made, and holds no line of either body.
    let e = edition::make(crate_with("//! fixture\n"), Kind::HandOut).unwrap();
    let fixture = e.files.iter().find(|f| f.path == "src/fixture.rs").unwrap();
    let text = String::from_utf8_lossy(&fixture.bytes);
    assert!(
        text.contains("crate::exercise::todo(\"disc_polar\")") && !text.contains("cbrt()"),
        "{text}"
    );
    assert_eq!(e.removed.len(), 3);
}
