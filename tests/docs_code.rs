//! Every Rust block of README.md and the user guide (docs/guide/*.md) is code the tests
//! compile: each is preceded by a `<!-- excerpt: PATH -->` line naming a file of the
//! repository that the build compiles (an example or a test), and its lines appear in that
//! file in one contiguous run, character for character. A block without the line, with a
//! file that does not exist, or that drifted from its file fails here; `rust,ignore` and
//! `rust,no_run` blocks are refused (a guide shows only code that builds).
use std::path::{Path, PathBuf};

/// The markdown files whose Rust blocks must be compiled code.
fn documents(root: &Path) -> Vec<PathBuf> {
    let mut docs = vec![root.join("README.md")];
    let guide = root.join("docs/guide");
    let mut chapters: Vec<PathBuf> = std::fs::read_dir(&guide)
        .expect("docs/guide")
        .map(|e| e.expect("guide entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    chapters.sort();
    docs.extend(chapters);
    docs
}

/// (line number of the fence, info string, the excerpt path if any, the block's lines).
fn rust_blocks(text: &str) -> Vec<(usize, String, Option<String>, Vec<String>)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut blocks = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if let Some(info) = line.strip_prefix("```") {
            let info = info.trim().to_string();
            let start = i;
            let mut body = Vec::new();
            i += 1;
            while i < lines.len() && !lines[i].starts_with("```") {
                body.push(lines[i].to_string());
                i += 1;
            }
            if info == "rust" || info.starts_with("rust,") {
                let excerpt = lines[..start]
                    .iter()
                    .rev()
                    .find(|l| !l.trim().is_empty())
                    .and_then(|l| l.trim().strip_prefix("<!-- excerpt: "))
                    .and_then(|l| l.strip_suffix(" -->"))
                    .map(str::to_string);
                blocks.push((start + 1, info, excerpt, body));
            }
        }
        i += 1;
    }
    blocks
}

/// Whether `block` occurs in `file` as one contiguous run of lines.
fn contains_run(file: &[&str], block: &[String]) -> bool {
    !block.is_empty()
        && file
            .windows(block.len())
            .any(|w| w.iter().zip(block).all(|(a, b)| *a == b.as_str()))
}

#[test]
fn every_rust_block_is_an_excerpt_of_compiled_code() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut problems = Vec::new();
    let mut checked = 0;
    for doc in documents(root) {
        let text = std::fs::read_to_string(&doc).expect("readable markdown");
        let name = doc.strip_prefix(root).unwrap_or(&doc).display().to_string();
        for (line, info, excerpt, body) in rust_blocks(&text) {
            if info != "rust" {
                problems.push(format!(
                    "{name}:{line}: ```{info} (only compiled code: ```rust)"
                ));
                continue;
            }
            let Some(path) = excerpt else {
                problems.push(format!(
                    "{name}:{line}: no <!-- excerpt: PATH --> line before it"
                ));
                continue;
            };
            if !(path.contains("/examples/")
                || path.starts_with("examples/")
                || path.contains("/tests/")
                || path.starts_with("tests/"))
            {
                problems.push(format!("{name}:{line}: {path} is not an example or a test"));
                continue;
            }
            let Ok(file) = std::fs::read_to_string(root.join(&path)) else {
                problems.push(format!("{name}:{line}: {path} does not exist"));
                continue;
            };
            let file_lines: Vec<&str> = file.lines().collect();
            if !contains_run(&file_lines, &body) {
                problems.push(format!(
                    "{name}:{line}: the block is not a run of {path}'s lines"
                ));
            }
            checked += 1;
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(
        checked >= 4,
        "only {checked} Rust blocks found: the quick starts are missing"
    );
}
