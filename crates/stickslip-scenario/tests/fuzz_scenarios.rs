//! No scenario file crashes, hangs or lies: the shipped scenarios, mutated (a number replaced
//! by a hostile one — NaN, ±∞, 1e39, 1e300, subnormals, huge integers —, a line deleted or
//! duplicated, a character replaced), either fail with a typed error naming a field, or
//! build and run (up to 25 steps) to a summary whose every number is finite. Deterministic
//! (fixed seed; `PROPTEST_CASES` / `PROPTEST_RNG_SEED` override, `scripts/long_tests.sh`
//! runs many fresh cases).

#[path = "../../../tests/support/deterministic.rs"]
mod support;

use proptest::prelude::*;
use stickslip_scenario::{Runner, Scenario};
use support::deterministic;

fn shipped() -> Vec<(String, String)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect()
}

const HOSTILE: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "1e39",
    "-1e39",
    "1e300",
    "-1e300",
    "0",
    "-0.0",
    "1e-320",
    "1e-45",
    "4294967296",
    "1000000000",
    "-1",
    "9223372036854775807",
    "1e13",
    "0.5",
];

/// Byte ranges of the number tokens of `text` (outside comments).
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let code = line.split('#').next().unwrap_or("");
        let bytes = code.as_bytes();
        let mut i = 0;
        while i < bytes.len() {
            let starts = bytes[i].is_ascii_digit()
                || (bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit));
            let inside_word =
                i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
            if starts && !inside_word {
                let mut j = i + 1;
                while j < bytes.len()
                    && (bytes[j].is_ascii_alphanumeric() || b".-+_".contains(&bytes[j]))
                {
                    j += 1;
                }
                out.push((offset + i, offset + j));
                i = j;
            } else {
                i += 1;
            }
        }
        offset += line.len();
    }
    out
}

#[derive(Debug, Clone)]
enum Mutation {
    Number { which: usize, value: usize },
    DeleteLine(usize),
    DuplicateLine(usize),
    ReplaceChar { at: usize, with: char },
}

fn mutation() -> impl Strategy<Value = Vec<Mutation>> {
    let one = prop_oneof![
        6 => (any::<usize>(), 0..HOSTILE.len())
            .prop_map(|(which, value)| Mutation::Number { which, value }),
        1 => any::<usize>().prop_map(Mutation::DeleteLine),
        1 => any::<usize>().prop_map(Mutation::DuplicateLine),
        1 => (any::<usize>(), prop::sample::select(vec!['"', '[', ']', '=', '1', 'x', '\n', '.']))
            .prop_map(|(at, with)| Mutation::ReplaceChar { at, with }),
    ];
    prop::collection::vec(one, 1..4)
}

fn apply(text: &str, m: &Mutation) -> String {
    match m {
        Mutation::Number { which, value } => {
            let spans = numbers(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (a, b) = spans[which % spans.len()];
            format!("{}{}{}", &text[..a], HOSTILE[*value], &text[b..])
        }
        Mutation::DeleteLine(k) | Mutation::DuplicateLine(k) => {
            let mut lines: Vec<&str> = text.lines().collect();
            let k = k % lines.len().max(1);
            if matches!(m, Mutation::DeleteLine(_)) {
                lines.remove(k);
            } else {
                let l = lines[k];
                lines.insert(k, l);
            }
            lines.join("\n")
        }
        Mutation::ReplaceChar { at, with } => {
            let chars: Vec<char> = text.chars().collect();
            let at = at % chars.len().max(1);
            chars
                .iter()
                .enumerate()
                .map(|(i, c)| if i == at { *with } else { *c })
                .collect()
        }
    }
}

proptest! {
    #![proptest_config(deterministic(256))]

    #[test]
    fn mutated_scenarios_fail_typed_or_run_finite(
        file in any::<prop::sample::Index>(),
        mutations in mutation(),
    ) {
        let files = shipped();
        let (name, text) = &files[file.index(files.len())];
        let text = mutations.iter().fold(text.clone(), |t, m| apply(&t, m));
        let scenario = match Scenario::from_toml_str_named(&text, name) {
            Ok(s) => s,
            Err(e) => {
                // Typed, and says where whenever it is about a value.
                prop_assert!(!e.to_string().is_empty());
                if e.build_error().is_some() {
                    prop_assert!(e.field().is_some_and(|f| !f.is_empty()), "{e}");
                }
                return Ok(());
            }
        };
        let scene = match scenario.build() {
            Ok(s) => s,
            Err(e) => {
                prop_assert!(!e.field().is_empty(), "{e}");
                return Ok(());
            }
        };
        let steps = scene.steps.min(25);
        let mut runner = Runner::new(scene);
        runner.run(steps);
        let summary = runner.summary();
        let json = serde_json::to_string(&summary).unwrap();
        prop_assert!(summary.finite, "{name} {mutations:?}: non-finite run\n{json}");
        prop_assert!(!json.contains("null"), "{name} {mutations:?}: non-finite number\n{json}");
    }
}
