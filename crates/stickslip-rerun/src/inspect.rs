//! Reading recordings back with rerun's own decoder (`re_log_encoding`) and chunk type: what
//! entities, timelines, rows and values an `.rrd` (or an in-memory recording) holds. Used by
//! the tests to check that a recording matches the simulation.

use rerun::external::arrow::array::{Array, Float64Array, UInt16Array};
use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Why a recording could not be read.
#[derive(Debug, thiserror::Error)]
pub enum InspectError {
    /// The file could not be opened.
    #[error("cannot open {path}: {source}")]
    Io {
        /// The path.
        path: String,
        /// The error.
        #[source]
        source: std::io::Error,
    },
    /// rerun's decoder rejected the data.
    #[error("rerun could not decode the recording: {0}")]
    Decode(String),
}

/// One entity of a recording.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EntityContents {
    /// Component identifiers logged statically (e.g. `Boxes3D:half_sizes`).
    pub static_components: BTreeSet<String>,
    /// Component identifiers logged on timelines.
    pub temporal_components: BTreeSet<String>,
    /// Timelines the temporal rows are indexed by.
    pub timelines: BTreeSet<String>,
    /// `step` value of every temporal row, sorted.
    pub steps: Vec<i64>,
    /// `sim_time` value (s) of every temporal row, in the order of `steps`.
    pub sim_times: Vec<f64>,
    /// Per component identifier: instances per temporal row, in the order of `steps`.
    pub instances: BTreeMap<String, Vec<usize>>,
    /// `Scalars:scalars` values per temporal row, in the order of `steps`.
    pub scalars: Vec<f64>,
    /// `*:class_ids` values of every temporal row, concatenated in the order of `steps`.
    pub class_ids: Vec<Vec<u16>>,
}

/// What a recording holds.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RrdContents {
    /// Application ids of the recordings in the stream.
    pub application_ids: BTreeSet<String>,
    /// Every timeline used.
    pub timelines: BTreeSet<String>,
    /// Entities by path (e.g. `world/bodies/block`).
    pub entities: BTreeMap<String, EntityContents>,
    /// Number of chunks decoded (of the recording; the viewer layout is apart).
    pub chunks: usize,
    /// Chunks of a blueprint (the viewer layout) sent with the recording.
    pub blueprint_chunks: usize,
}

impl RrdContents {
    /// The entity at `path`.
    pub fn entity(&self, path: &str) -> Option<&EntityContents> {
        self.entities.get(path)
    }

    /// Entity paths under `prefix` (`prefix` itself excluded).
    pub fn children(&self, prefix: &str) -> Vec<&str> {
        let p = format!("{}/", prefix.trim_end_matches('/'));
        self.entities
            .keys()
            .filter(|k| k.starts_with(&p))
            .map(String::as_str)
            .collect()
    }
}

/// Decodes an `.rrd` file.
pub fn read_rrd(path: impl AsRef<Path>) -> Result<RrdContents, InspectError> {
    let path = path.as_ref();
    let file = std::fs::File::open(path).map_err(|source| InspectError::Io {
        path: path.display().to_string(),
        source,
    })?;
    read_from(std::io::BufReader::new(file))
}

/// Decodes `.rrd` bytes (e.g. `MemorySinkStorage::drain_as_bytes`).
pub fn read_rrd_bytes(bytes: &[u8]) -> Result<RrdContents, InspectError> {
    read_from(std::io::BufReader::new(bytes))
}

fn read_from<R: std::io::BufRead>(reader: R) -> Result<RrdContents, InspectError> {
    let decoder =
        DecoderApp::decode_eager(reader).map_err(|e| InspectError::Decode(e.to_string()))?;
    let mut messages = Vec::new();
    for msg in decoder {
        messages.push(msg.map_err(|e| InspectError::Decode(e.to_string()))?);
    }
    contents(&messages)
}

/// Summarizes decoded messages.
pub fn contents(messages: &[LogMsg]) -> Result<RrdContents, InspectError> {
    let mut out = RrdContents::default();
    // Rows of each entity, to be sorted by step afterwards.
    type Row = (
        i64,
        f64,
        BTreeMap<String, usize>,
        Option<f64>,
        Option<Vec<u16>>,
    );
    let mut rows: BTreeMap<String, Vec<Row>> = BTreeMap::new();
    for msg in messages {
        match msg {
            LogMsg::SetStoreInfo(info) => {
                out.application_ids
                    .insert(info.info.application_id().to_string());
            }
            LogMsg::ArrowMsg(store, _) if store.kind() == rerun::StoreKind::Blueprint => {
                out.blueprint_chunks += 1;
            }
            LogMsg::ArrowMsg(_, arrow) => {
                let chunk = Chunk::from_arrow_msg(arrow)
                    .map_err(|e| InspectError::Decode(e.to_string()))?;
                out.chunks += 1;
                let path = chunk.entity_path().to_string();
                let path = path.trim_start_matches('/').to_string();
                let entity = out.entities.entry(path.clone()).or_default();
                if chunk.is_static() {
                    for d in chunk.component_descriptors() {
                        entity.static_components.insert(d.component.to_string());
                    }
                    continue;
                }
                for name in chunk.timelines().keys() {
                    out.timelines.insert(name.to_string());
                    entity.timelines.insert(name.to_string());
                }
                let step_col = chunk
                    .timelines()
                    .iter()
                    .find(|(n, _)| n.as_str() == crate::paths::STEP)
                    .map(|(_, c)| c.times_raw().to_vec());
                let time_col = chunk
                    .timelines()
                    .iter()
                    .find(|(n, _)| n.as_str() == crate::paths::SIM_TIME)
                    .map(|(_, c)| c.times_raw().to_vec());
                let n = chunk.num_rows();
                let mut chunk_rows: Vec<Row> = (0..n)
                    .map(|i| {
                        (
                            step_col.as_ref().map_or(-1, |c| c[i]),
                            time_col.as_ref().map_or(f64::NAN, |c| c[i] as f64 * 1e-9),
                            BTreeMap::new(),
                            None,
                            None,
                        )
                    })
                    .collect();
                for (id, column) in chunk.components().iter() {
                    let id = id.to_string();
                    entity.temporal_components.insert(id.clone());
                    let list = &column.list_array;
                    for (i, row) in chunk_rows.iter_mut().enumerate() {
                        if list.is_null(i) {
                            continue;
                        }
                        let values = list.value(i);
                        row.2.insert(id.clone(), values.len());
                        if id.ends_with(":scalars")
                            && let Some(f) = values.as_any().downcast_ref::<Float64Array>()
                            && !f.is_empty()
                        {
                            row.3 = Some(f.value(0));
                        }
                        if id.ends_with(":class_ids")
                            && let Some(c) = values.as_any().downcast_ref::<UInt16Array>()
                        {
                            row.4 = Some(c.values().to_vec());
                        }
                    }
                }
                rows.entry(path).or_default().extend(chunk_rows);
            }
            LogMsg::BlueprintActivationCommand(_) => {}
        }
    }
    for (path, mut rs) in rows {
        rs.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let entity = out.entities.entry(path).or_default();
        for (step, time, inst, scalar, classes) in rs {
            entity.steps.push(step);
            entity.sim_times.push(time);
            for id in &entity.temporal_components {
                entity
                    .instances
                    .entry(id.clone())
                    .or_default()
                    .push(inst.get(id).copied().unwrap_or(0));
            }
            if let Some(s) = scalar {
                entity.scalars.push(s);
            }
            if let Some(c) = classes {
                entity.class_ids.push(c);
            }
        }
    }
    Ok(out)
}
