//! Every number a student reads on a sheet is written as an engineer writes it: at
//! most four significant digits (2.029 MN, not 2028973.2208 N), a value that is the
//! round-off of its neighbours as 0, no exponent noise. Checked on the text of every
//! shipped scene's position sheet (pose, polygons, tables, force polygons where the
//! scene has them) at 12 inputs over its range, and of its course sheet.

use crate::common;

use linkage::Kinematics;
use linkage_diagram::course::CourseSheet;
use linkage_diagram::svg_course::course_sheet;
use linkage_diagram::words::Lang;

/// The text a reader sees: what lies between `>` and `<` in the SVG, outside tags.
fn texts(svg: &str) -> Vec<String> {
    svg.split('<')
        .filter_map(|piece| piece.split_once('>').map(|(_, text)| text.trim()))
        .filter(|t| !t.is_empty())
        .map(str::to_string)
        .collect()
}

/// The numbers in `text` with their significant digits: a run of digits (with a
/// decimal point) not glued to a letter before it, as "R12" or "P13" are names. A
/// whole number's trailing zeros are not significant (a tick at 10000, a round step).
fn numbers(text: &str) -> Vec<(String, usize)> {
    let chars: Vec<char> = text.chars().collect();
    let mut found = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if !chars[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        let named = i > 0 && (chars[i - 1].is_alphabetic() || chars[i - 1] == '_');
        let start = i;
        while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
            i += 1;
        }
        if named {
            continue;
        }
        let token: String = chars[start..i].iter().collect();
        let digits: String = token.chars().filter(char::is_ascii_digit).collect();
        let digits = digits.trim_start_matches('0');
        let digits = if token.contains('.') {
            digits
        } else {
            digits.trim_end_matches('0')
        };
        found.push((token, digits.len()));
    }
    found
}

fn check(svg: &str, what: &str) {
    for text in texts(svg) {
        // Rust writes a non-finite number as NaN or inf; an exponent as 1e-17.
        let words = text.split(|c: char| !c.is_alphanumeric() && c != '-');
        for word in words {
            let noise = word == "NaN"
                || word == "inf"
                || word.strip_prefix('-') == Some("inf")
                || (word.starts_with(|c: char| c.is_ascii_digit()) && has_exponent(word));
            assert!(!noise, "{what}: {word:?} in {text:?}");
        }
        for (token, significant) in numbers(&text) {
            assert!(
                significant <= 4,
                "{what}: {token} in {text:?} has {significant} significant digits"
            );
        }
    }
}

#[test]
fn the_readers_numbers() {
    assert_eq!(
        numbers("F_R12 = 2028973.2208 N at 12.5°, P13"),
        vec![("2028973.2208".into(), 11), ("12.5".into(), 3)]
    );
    assert_eq!(numbers("0.001275 m/s"), vec![("0.001275".into(), 4)]);
    assert_eq!(
        numbers("10000, 2028973"),
        vec![("10000".into(), 1), ("2028973".into(), 7)]
    );
    assert_eq!(
        texts("<g><text x=\"1\">a <tspan>b</tspan></text></g>"),
        ["a", "b"]
    );
}

#[test]
fn every_sheet_writes_four_significant_digits_at_most() {
    for (file, m) in common::scenes() {
        let mut k = Kinematics::new(m.clone()).expect("kinematics");
        for x in common::inputs(&k, 12) {
            let what = format!("{file} at {:.1} deg", x.to_degrees());
            for lang in Lang::ALL {
                let Some(sheet) = common::full_sheet(&mut k, x, lang) else {
                    continue;
                };
                check(&sheet.pages.concat(), &what);
            }
        }
        let course = CourseSheet::compute(&mut k, 12, &[1, 11]).expect("course sheet");
        for lang in Lang::ALL {
            check(
                &course_sheet(&course, lang).pages.concat(),
                &format!("{file}: course sheet"),
            );
        }
    }
}

/// Whether `word` (starting with a digit) holds an exponent: a digit, `e`, then a
/// digit or a sign (1e-17, 5e5, 2.5e+3).
fn has_exponent(word: &str) -> bool {
    let c: Vec<char> = word.chars().collect();
    c.windows(3).any(|w| {
        w[0].is_ascii_digit()
            && w[1] == 'e'
            && (w[2].is_ascii_digit() || w[2] == '-' || w[2] == '+')
    })
}
