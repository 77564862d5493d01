//! The small markup of the diagrams' labels (italic, bold, monospace, subscripts and
//! superscripts), read into runs of text in one style.

/// One run of text in one style: italic, bold, and its script level (0 on the baseline,
/// 1 a subscript, -1 a superscript).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Run {
    pub(super) text: String,
    pub(super) italic: bool,
    pub(super) bold: bool,
    pub(super) code: bool,
    pub(super) script: i8,
}

/// The runs of a label written in a small markup: `*…*` italic, `~…~` bold, `` `…` ``
/// monospace (a name of the scene file or the code), `_x`, `_*x*`
/// or `_{…}` a subscript, `^x`, `^*x*` or `^{…}` a superscript, `\` takes the next
/// character literally. Unicode does the rest (θ, ω, λ, n₁, r̂).
pub(super) fn runs(markup: &str) -> Vec<Run> {
    let mut out: Vec<Run> = Vec::new();
    let (mut italic, mut bold, mut code) = (false, false, false);
    let mut push = |c: char, italic: bool, bold: bool, code: bool, script: i8| match out.last_mut()
    {
        Some(r) if r.italic == italic && r.bold == bold && r.code == code && r.script == script => {
            r.text.push(c);
        }
        _ => out.push(Run {
            text: c.to_string(),
            italic,
            bold,
            code,
            script,
        }),
    };
    let mut chars = markup.chars();
    while let Some(c) = chars.next() {
        match c {
            '*' => italic = !italic,
            '~' => bold = !bold,
            '`' => code = !code,
            '\\' => {
                if let Some(n) = chars.next() {
                    push(n, italic, bold, code, 0);
                }
            }
            '_' | '^' if code => push(c, italic, bold, code, 0),
            '_' | '^' => {
                let script = if c == '_' { 1 } else { -1 };
                let mut group = String::new();
                match chars.next() {
                    Some('{') => {
                        for g in chars.by_ref() {
                            if g == '}' {
                                break;
                            }
                            group.push(g);
                        }
                    }
                    // `_*ω*`: an italic script of the letters up to the closing `*`.
                    Some('*') => {
                        group.push('*');
                        for g in chars.by_ref() {
                            group.push(g);
                            if g == '*' {
                                break;
                            }
                        }
                    }
                    Some(g) => group.push(g),
                    None => {}
                }
                for g in group.chars() {
                    match g {
                        '*' => italic = !italic,
                        '~' => bold = !bold,
                        _ => push(g, italic, bold, code, script),
                    }
                }
            }
            _ => push(c, italic, bold, code, 0),
        }
    }
    out
}

/// The baseline shift of a script level, in units of the text's size (SVG's y grows down).
pub(super) fn shift(script: i8) -> f64 {
    match script {
        1 => 0.28,
        -1 => -0.42,
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_makes_italic_bold_code_and_script_runs() {
        let r = runs("*p*_*ω* = ~n̂~^{2*i*} `fov_y` max\\_depth");
        let parts: Vec<(&str, bool, bool, bool, i8)> = r
            .iter()
            .map(|r| (r.text.as_str(), r.italic, r.bold, r.code, r.script))
            .collect();
        assert_eq!(
            parts,
            [
                ("p", true, false, false, 0),
                ("ω", true, false, false, 1),
                (" = ", false, false, false, 0),
                ("n̂", false, true, false, 0),
                ("2", false, false, false, -1),
                ("i", true, false, false, -1),
                (" ", false, false, false, 0),
                ("fov_y", false, false, true, 0),
                (" max_depth", false, false, false, 0),
            ]
        );
    }
}
