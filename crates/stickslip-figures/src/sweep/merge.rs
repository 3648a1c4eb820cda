//! Putting a sharded sweep back together: [`merge`] reads the shard files
//! ([`super::shard_file`]), checks that they are the `N` shards of one grid written by this
//! version, and returns the whole sweep, whose [`Merged::write`] is byte for byte the
//! unsharded run's output.
//!
//! The checks, each error naming the file: every file is a shard file of
//! [`FORMAT_VERSION`] written by [`TOOL_VERSION`]; all have the kind, grid fingerprint, grid
//! size and shard count of the first; no shard comes twice and none is missing (the message
//! lists the missing tasks, ready for `sbatch --array=…`); each file's indices are its
//! shard's slice, its points are as many and sit at those grid coordinates, and its grid
//! still has the fingerprint it was written with.

use super::exact::Exact;
use super::feeder::{FeederPoint, FeederSweep};
use super::popov::{PopovPoint, PopovSweep};
use super::shard::Shard;
use super::shard_file::{
    FORMAT, FORMAT_VERSION, ShardFile, Sharded, TOOL_VERSION, fingerprint, stem,
};
use crate::FigureError;
use serde::de::IgnoredAny;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why shards could not be merged.
#[derive(Debug, Error)]
pub enum MergeError {
    /// A file or directory could not be read.
    #[error("cannot read {}: {message}", path.display())]
    Read {
        /// The path.
        path: PathBuf,
        /// The system's message.
        message: String,
    },
    /// No shard files were found.
    #[error("no shard files (NAME.shard-K-of-N.json) in {}", path.display())]
    NoShards {
        /// The directory searched.
        path: PathBuf,
    },
    /// A file is not a shard file this version can read.
    #[error("{}: not a stickslip shard file: {reason}", path.display())]
    NotShard {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        reason: String,
    },
    /// A file was written by another version of stickslip.
    #[error(
        "{}: written by stickslip {found}, this is stickslip {TOOL_VERSION} (mixed versions: \
         rerun that shard with this version)",
        path.display()
    )]
    Version {
        /// The file.
        path: PathBuf,
        /// Its writer's version.
        found: String,
    },
    /// A file belongs to another sweep or another split than the first file.
    #[error(
        "{}: {what} {found}, but {} has {expected} (shards of different sweeps cannot be merged)",
        path.display(),
        first.display()
    )]
    Mixed {
        /// The file.
        path: PathBuf,
        /// The first file.
        first: PathBuf,
        /// What differs (kind, grid fingerprint, grid size, shard count).
        what: &'static str,
        /// The file's value.
        found: String,
        /// The first file's value.
        expected: String,
    },
    /// Two files are the same shard: their points would be counted twice.
    #[error(
        "{} and {} are both shard {shard} (duplicated points)",
        first.display(),
        path.display()
    )]
    Duplicate {
        /// The second file.
        path: PathBuf,
        /// The first file with that shard.
        first: PathBuf,
        /// The shard.
        shard: Shard,
    },
    /// Some shards are missing.
    #[error(
        "missing {} of {count} shards: task(s) {} (the first would have written {}); rerun \
         them (sbatch --array={})",
        missing.len(),
        list(missing),
        example.display(),
        list(missing)
    )]
    Missing {
        /// The missing tasks (1-based).
        missing: Vec<usize>,
        /// N.
        count: usize,
        /// The file the first missing shard would have written.
        example: PathBuf,
    },
    /// A file's contents contradict themselves (indices, points or grid).
    #[error("{}: {reason}", path.display())]
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        reason: String,
    },
    /// The merged sweep's grid is invalid.
    #[error("{}: {source}", path.display())]
    Sweep {
        /// The file.
        path: PathBuf,
        /// The sweep's error.
        source: FigureError,
    },
}

/// `1,3,5` (at most 50 numbers, then `…`).
fn list(tasks: &[usize]) -> String {
    let mut out: Vec<String> = tasks.iter().take(50).map(|k| k.to_string()).collect();
    if tasks.len() > 50 {
        out.push("…".into());
    }
    out.join(",")
}

/// A merged sweep.
#[derive(Debug, Clone, PartialEq)]
pub enum Merged {
    /// A Popov sweep and its points in grid order.
    Popov(PopovSweep, Vec<PopovPoint>),
    /// A feeder sweep and its points in grid order.
    Feeder(FeederSweep, Vec<FeederPoint>),
}

impl Merged {
    /// Writes the unsharded output (CSV, JSON, heat maps) into `dir`; returns the paths.
    pub fn write(&self, dir: &Path) -> Result<Vec<PathBuf>, FigureError> {
        match self {
            Merged::Popov(sweep, points) => sweep.write(dir, points),
            Merged::Feeder(sweep, points) => sweep.write(dir, points),
        }
    }

    /// Points in the grid.
    pub fn len(&self) -> usize {
        match self {
            Merged::Popov(_, p) => p.len(),
            Merged::Feeder(_, p) => p.len(),
        }
    }

    /// Whether the grid is empty (never, for a valid sweep).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// The shard files among `inputs`: files as given, and for a directory its
/// `NAME.shard-K-of-N.json` files in name order.
pub fn shard_files(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, MergeError> {
    let mut files = Vec::new();
    for input in inputs {
        let read = |e: std::io::Error| MergeError::Read {
            path: input.clone(),
            message: e.to_string(),
        };
        if input.is_dir() {
            let mut found: Vec<PathBuf> = std::fs::read_dir(input)
                .map_err(read)?
                .filter_map(|entry| entry.ok().map(|e| e.path()))
                .filter(|p| {
                    p.file_name()
                        .and_then(|n| n.to_str())
                        .is_some_and(|n| n.contains(".shard-") && n.ends_with(".json"))
                })
                .collect();
            if found.is_empty() {
                return Err(MergeError::NoShards {
                    path: input.clone(),
                });
            }
            found.sort();
            files.append(&mut found);
        } else {
            files.push(input.clone());
        }
    }
    Ok(files)
}

/// One shard file read, with the fields every kind shares.
struct Read {
    path: PathBuf,
    text: String,
    head: ShardFile<IgnoredAny, IgnoredAny>,
}

/// Reads and checks the shard files `files` (see [`shard_files`]) and puts the sweep back
/// together.
pub fn merge(files: &[PathBuf]) -> Result<Merged, MergeError> {
    let Some(first_path) = files.first() else {
        return Err(MergeError::NoShards { path: ".".into() });
    };
    let mut shards: Vec<Read> = Vec::with_capacity(files.len());
    for path in files {
        shards.push(read_head(path)?);
    }
    let first = &shards[0];
    for s in &shards[1..] {
        let mixed = |what, found: String, expected: String| MergeError::Mixed {
            path: s.path.clone(),
            first: first_path.clone(),
            what,
            found,
            expected,
        };
        let (a, b) = (&s.head, &first.head);
        if a.kind != b.kind {
            return Err(mixed("kind", a.kind.clone(), b.kind.clone()));
        }
        if a.fingerprint != b.fingerprint || a.total != b.total {
            return Err(mixed(
                "grid",
                format!("{} ({} points)", a.fingerprint, a.total),
                format!("{} ({} points)", b.fingerprint, b.total),
            ));
        }
        if a.shard.count() != b.shard.count() {
            return Err(mixed(
                "shard count",
                a.shard.count().to_string(),
                b.shard.count().to_string(),
            ));
        }
    }
    let count = first.head.shard.count();
    let mut by_task: BTreeMap<usize, &Read> = BTreeMap::new();
    for s in &shards {
        if let Some(other) = by_task.insert(s.head.shard.index(), s) {
            return Err(MergeError::Duplicate {
                path: s.path.clone(),
                first: other.path.clone(),
                shard: s.head.shard,
            });
        }
    }
    let missing: Vec<usize> = (1..=count).filter(|k| !by_task.contains_key(k)).collect();
    if let Some(&k) = missing.first() {
        let dir = first_path.parent().unwrap_or(Path::new(""));
        let shard = Shard::new(k, count).map_err(|e| MergeError::NotShard {
            path: first_path.clone(),
            reason: e.to_string(),
        })?;
        return Err(MergeError::Missing {
            missing,
            count,
            example: dir.join(format!("{}.json", stem(&first.head.kind, shard))),
        });
    }
    let ordered: Vec<&Read> = by_task.into_values().collect();
    match first.head.kind.as_str() {
        "popov" => merge_kind::<PopovSweep>(&ordered).map(|(s, p)| Merged::Popov(s, p)),
        "feeder" => merge_kind::<FeederSweep>(&ordered).map(|(s, p)| Merged::Feeder(s, p)),
        other => Err(MergeError::NotShard {
            path: first.path.clone(),
            reason: format!("unknown sweep kind `{other}`"),
        }),
    }
}

/// Reads `path` and checks its format and version.
fn read_head(path: &Path) -> Result<Read, MergeError> {
    let text = std::fs::read_to_string(path).map_err(|e| MergeError::Read {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    let not_shard = |reason: String| MergeError::NotShard {
        path: path.to_path_buf(),
        reason,
    };
    // The format first, alone, so a file of another format or version says so rather than
    // failing on a field it lacks.
    #[derive(serde::Deserialize)]
    struct Format {
        format: String,
        format_version: u32,
        tool_version: String,
    }
    let format: Format = serde_json::from_str(&text).map_err(|e| not_shard(e.to_string()))?;
    if format.format != FORMAT {
        return Err(not_shard(format!(
            "its format is `{}`, not `{FORMAT}`",
            format.format
        )));
    }
    if format.format_version != FORMAT_VERSION {
        return Err(not_shard(format!(
            "format version {}, this stickslip reads version {FORMAT_VERSION}",
            format.format_version
        )));
    }
    if format.tool_version != TOOL_VERSION {
        return Err(MergeError::Version {
            path: path.to_path_buf(),
            found: format.tool_version,
        });
    }
    let head = serde_json::from_str(&text).map_err(|e| not_shard(e.to_string()))?;
    Ok(Read {
        path: path.to_path_buf(),
        text,
        head,
    })
}

/// Reads the shards (tasks 1..=N in order, already checked to agree) as sweeps of kind `S`
/// and assembles the points in grid order.
fn merge_kind<S: Sharded>(shards: &[&Read]) -> Result<(S, Vec<S::Point>), MergeError> {
    let mut sweep: Option<S> = None;
    let mut slots: Vec<Option<S::Point>> = Vec::new();
    for s in shards {
        let invalid = |reason: String| MergeError::Invalid {
            path: s.path.clone(),
            reason,
        };
        let file: ShardFile<Exact<S>, Exact<S::Point>> =
            serde_json::from_str(&s.text).map_err(|e| MergeError::NotShard {
                path: s.path.clone(),
                reason: e.to_string(),
            })?;
        let this = file.sweep.0;
        let total = this.total().map_err(|source| MergeError::Sweep {
            path: s.path.clone(),
            source,
        })?;
        let print = fingerprint(&this).map_err(|source| MergeError::Sweep {
            path: s.path.clone(),
            source,
        })?;
        if print != file.fingerprint {
            return Err(invalid(format!(
                "its grid has fingerprint {print}, the file says {} (edited?)",
                file.fingerprint
            )));
        }
        if total != file.total {
            return Err(invalid(format!(
                "its grid has {total} points, the file says {}",
                file.total
            )));
        }
        if file.indices != file.shard.indices(total) {
            return Err(invalid(format!(
                "its point indices are not shard {}'s slice of {total} points",
                file.shard
            )));
        }
        if file.points.len() != file.indices.len() {
            return Err(invalid(format!(
                "{} points for {} indices",
                file.points.len(),
                file.indices.len()
            )));
        }
        let points: Vec<S::Point> = file.points.into_iter().map(|p| p.0).collect();
        if let Some(i) = this.off_grid(&file.indices, &points) {
            return Err(invalid(format!(
                "its point for index {i} is not at the grid's coordinates there"
            )));
        }
        if sweep.is_none() {
            slots = (0..total).map(|_| None).collect();
            sweep = Some(this);
        }
        for (i, p) in file.indices.into_iter().zip(points) {
            let slot = slots
                .get_mut(i)
                .ok_or_else(|| invalid(format!("index {i} is off the grid")))?;
            if slot.replace(p).is_some() {
                return Err(invalid(format!("point {i} is in another shard too")));
            }
        }
    }
    let Some(sweep) = sweep else {
        return Err(MergeError::NoShards { path: ".".into() });
    };
    let mut points = Vec::with_capacity(slots.len());
    for (i, slot) in slots.into_iter().enumerate() {
        match slot {
            Some(p) => points.push(p),
            None => {
                return Err(MergeError::Invalid {
                    path: shards[0].path.clone(),
                    reason: format!("no shard holds point {i}"),
                });
            }
        }
    }
    Ok((sweep, points))
}

#[cfg(test)]
mod tests {
    use super::super::Range;
    use super::super::shard_file::write_shard;
    use super::*;
    use stickslip_core::waveform::WaveformKind;

    /// A theory-only Popov sweep of 2 × 5 × 3 = 30 points (no rapier worlds: fast).
    fn sweep() -> PopovSweep {
        PopovSweep {
            waveforms: vec![WaveformKind::Sine, WaveformKind::Square],
            beta: Range {
                lo: 0.5,
                hi: 12.0,
                n: 5,
            },
            alpha: Range {
                lo: 0.2,
                hi: 0.8,
                n: 3,
            },
            rapier: false,
            drive: crate::sweep::popov::Drive::Resolved,
        }
    }

    fn tmp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!(
            "stickslip-merge-unit-{name}-{}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    /// Writes all `count` shards of `sweep` into `dir`; returns the JSON files by task.
    fn write_all(sweep: &PopovSweep, count: usize, dir: &Path) -> Vec<PathBuf> {
        (1..=count)
            .map(|k| {
                let shard = Shard::new(k, count).unwrap();
                let idx = shard.indices(sweep.validate().unwrap());
                let points = sweep.run_indices(&idx, 1, &|| ()).unwrap();
                write_shard(dir, sweep, shard, &points).unwrap()[1].clone()
            })
            .collect()
    }

    #[test]
    fn shards_merge_to_the_whole_sweep() {
        let s = sweep();
        let whole = s.run(2, &|| ()).unwrap();
        for count in [1, 2, 7, 30, 31] {
            let dir = tmp(&format!("ok{count}"));
            write_all(&s, count, &dir);
            let files = shard_files(std::slice::from_ref(&dir)).unwrap();
            assert_eq!(files.len(), count);
            assert_eq!(
                merge(&files).unwrap(),
                Merged::Popov(s.clone(), whole.clone())
            );
            let _ = std::fs::remove_dir_all(&dir);
        }
    }

    fn edit(path: &Path, from: &str, to: &str) {
        let text = std::fs::read_to_string(path).unwrap();
        assert!(text.contains(from), "{from} in {}", path.display());
        std::fs::write(path, text.replacen(from, to, 1)).unwrap();
    }

    fn err(files: &[PathBuf]) -> String {
        merge(files).unwrap_err().to_string()
    }

    #[test]
    fn bad_sets_of_shards_are_errors_naming_the_file() {
        let s = sweep();
        let dir = tmp("bad");
        let files = write_all(&s, 3, &dir);
        let name = |k: usize| files[k].display().to_string();

        let e = err(&files[..2]);
        assert!(
            e.contains("missing 1 of 3") && e.contains("--array=3"),
            "{e}"
        );
        assert!(e.contains("popov.shard-3-of-3.json"), "{e}");

        let e = err(&[files[0].clone(), files[1].clone(), files[1].clone()]);
        assert!(e.contains("duplicated") && e.contains(&name(1)), "{e}");

        let other = tmp("bad-other");
        let mut s2 = s.clone();
        s2.alpha.n = 4;
        let files2 = write_all(&s2, 3, &other);
        let e = err(&[files[0].clone(), files[1].clone(), files2[2].clone()]);
        assert!(e.contains("grid") && e.contains(&files2[2].display().to_string()));

        let files4 = write_all(&s, 4, &other);
        let e = err(&[files[0].clone(), files4[1].clone()]);
        assert!(e.contains("shard count 4") && e.contains("has 3"), "{e}");

        let text2 = std::fs::read_to_string(&files[2]).unwrap();
        edit(
            &files[2],
            "\"tool_version\": \"",
            "\"tool_version\": \"0.0.0-old",
        );
        let e = err(&files);
        assert!(e.contains("mixed versions") && e.contains(&name(2)), "{e}");
        std::fs::write(&files[2], &text2).unwrap();

        let text = std::fs::read_to_string(&files[1]).unwrap();
        edit(&files[1], "\"format_version\": 1", "\"format_version\": 9");
        assert!(err(&files).contains("format version 9"));
        std::fs::write(&files[1], &text).unwrap();
        edit(&files[1], "\"n\": 3", "\"n\": 2");
        let e = err(&files);
        assert!(e.contains("fingerprint") && e.contains(&name(1)), "{e}");

        std::fs::write(&files[1], "not json").unwrap();
        assert!(err(&files).contains("not a stickslip shard file"));
        std::fs::remove_file(&files[1]).unwrap();
        assert!(err(&files).contains("cannot read"));

        let empty = tmp("bad-empty");
        std::fs::create_dir_all(&empty).unwrap();
        let e = shard_files(std::slice::from_ref(&empty))
            .unwrap_err()
            .to_string();
        assert!(e.contains("no shard files"), "{e}");
        for d in [dir, other, empty] {
            let _ = std::fs::remove_dir_all(d);
        }
    }

    #[test]
    fn tampered_slices_and_points_are_errors() {
        let s = sweep();
        let dir = tmp("tamper");
        let files = write_all(&s, 2, &dir);
        let text = std::fs::read_to_string(&files[0]).unwrap();
        let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        // Another valid grid index in place of the first: no longer the shard's slice.
        let other = Shard::new(2, 2).unwrap().indices(30)[0];
        doc["indices"][0] = other.into();
        std::fs::write(&files[0], doc.to_string()).unwrap();
        assert!(err(&files).contains("not shard 1/2's slice"));
        // A point moved off its grid coordinates.
        let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        doc["points"][0]["beta"] = "7e0".into();
        std::fs::write(&files[0], doc.to_string()).unwrap();
        assert!(err(&files).contains("not at the grid's coordinates"));
        // A point dropped.
        let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        doc["points"].as_array_mut().unwrap().pop();
        std::fs::write(&files[0], doc.to_string()).unwrap();
        assert!(err(&files).contains("points for"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
