//! Snapshot and restore: save a world with stickslip and resume it bit-identically.
//!
//! rapier serializes its own world (`PhysicsWorld` with rapier's `serde-serialize` feature);
//! [`StickSlipSnapshot`] is the rest: everything the [`StickSlip`] modifier keeps except your
//! wrapped hooks `H` — the tuning, the default and per-collider materials, the attached
//! colliders and per-pair materials, the vibration sources, the colliders whose hook flag it
//! turned on and which of those it turned off again because their contacts are quiet
//! (recycled, with the poses their drift is measured from), the per-contact friction state
//! (law state, mean normal forces, and the slot/generation layout that rapier's manifolds
//! point at through their `user_data`), the last solve measured at each contact patch of a
//! composite shape (a clustered patch reads its next step from it), the rolling and spinning
//! resistance of touching pairs (their states and which of the world's joints carry them),
//! the clock, the totals and the last reports.
//! A world resumed from both continues exactly as the uninterrupted one, bit for bit.
//!
//! ## Save and resume a world
//! ```
//! # extern crate rapier as rapier3d;
//! use rapier3d::prelude::*;
//! use stickslip_core::law::{Coulomb, Law};
//! use stickslip_rapier::{StickSlip, WorldSnapshot};
//!
//! let mut world = PhysicsWorld::default();
//! let ground = world.insert_collider(ColliderBuilder::cuboid(5.0, 0.1, 5.0), None);
//! world.insert(
//!     RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.35, 0.0)),
//!     ColliderBuilder::cuboid(0.25, 0.25, 0.25),
//! );
//! let mut friction = StickSlip::new(Law::Coulomb(Coulomb::new(0.5).unwrap()));
//! friction.attach(&mut world.colliders, ground, None);
//! for _ in 0..30 {
//!     friction.step(&mut world);
//! }
//! // Save (any `std::io::Write`: a file, a socket, a Vec).
//! let mut bytes = Vec::new();
//! WorldSnapshot::save_from(&world, &friction, &mut bytes).unwrap();
//! // Resume (any `std::io::Read`); your own hooks go back in as the last argument.
//! let (mut resumed, mut resumed_friction) =
//!     WorldSnapshot::load(bytes.as_slice()).unwrap().restore(()).unwrap();
//! friction.step(&mut world);
//! resumed_friction.step(&mut resumed);
//! let (a, b) = (world.bodies.iter().next().unwrap().1, resumed.bodies.iter().next().unwrap().1);
//! assert_eq!(a.translation(), b.translation());
//! ```
//!
//! In memory, [`StickSlip::snapshot`] and [`StickSlip::restore`] do the same for the modifier
//! alone (pair it with your own copy of the rapier world, made with the same world state).
//!
//! ## Format
//! [`WorldSnapshot::save`] and [`StickSlipSnapshot::save`] write a 13-byte header — the magic
//! bytes `STKSLIP\0`, the format version ([`FORMAT_VERSION`], u32 little-endian) and one byte
//! for the content (0: modifier only, 1: world and modifier) — followed by the data in CBOR
//! (RFC 8949, through the `ciborium` crate): a compact binary encoding that keeps every f32 and
//! f64 exactly (NaN and infinities included, which JSON cannot), and that is self-describing,
//! which stickslip's tagged parameter enums need (the non-self-describing `bincode`/`postcard`
//! cannot decode them). Closure waveforms ([`stickslip_core::waveform::Waveform::from_fn`])
//! cannot be saved to a file ([`SnapshotError::Encode`]); in-memory snapshots keep them.
//!
//! ## Untrusted files
//! A snapshot file is checked before anything is built from it: [`StickSlip::restore`]
//! re-validates every parameter through the constructors (materials, vibration sources,
//! tuning), requires finite state, and checks the contact store's indices (slots, free list,
//! key map) for consistency, returning a [`SnapshotError`], never panicking. Nothing is
//! allocated by a number read from the file beyond the file's own size: per-collider tables
//! are only filled for colliders that exist in the collider set given to `restore` (entries
//! of colliders that are not in it can never be reached by a step and are dropped). rapier's
//! part is checked as far as rapier's own deserialization checks it; a panic inside it is
//! caught and returned as [`SnapshotError::Decode`].

use crate::collider_map::{ColliderBits, ColliderMap};
use crate::contact_store::{
    ContactKey, ContactRecord, ContactStore, INDEX_BITS, LiveImage, ManifoldPart, SlotImage,
    StoreImage,
};
use crate::measure::Measured;
use crate::modifier::{Clock, ReadBack, StickSlip, StickSlipConfig};
use crate::report::{ContactReport, WorldTotals};
use crate::rolling::{Resisting, ResistingPair};
use rapier::prelude::*;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::io::{Read, Write};
use stickslip_core::FrictionMaterial;
use stickslip_core::ParamError;
use stickslip_core::contact::ContactState;
use stickslip_core::contact::{
    Amplitude, VibrationComponent, VibrationDirection, VibrationMode, VibrationSource,
};
use stickslip_core::law::Regime;
use stickslip_core::waveform::Waveform;

/// Version of the snapshot format written by this build (and the only one it reads).
pub const FORMAT_VERSION: u32 = 7;

const MAGIC: [u8; 8] = *b"STKSLIP\0";
/// Header kind of a [`StickSlipSnapshot`] file.
#[doc(hidden)]
pub const KIND_MODIFIER: u8 = 0;
/// Header kind of a [`WorldSnapshot`] file.
#[doc(hidden)]
pub const KIND_WORLD: u8 = 1;

/// Why a snapshot could not be written, read or restored.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SnapshotError {
    /// Reading or writing failed.
    #[error("snapshot I/O failed: {0}")]
    Io(#[from] std::io::Error),
    /// The data does not start with a stickslip snapshot header (or is shorter than one).
    #[error("not a stickslip snapshot (missing or wrong header)")]
    NotASnapshot,
    /// The header names a format version this build does not read.
    #[error("snapshot format version {found} is not supported (this build reads {supported})")]
    UnsupportedVersion {
        /// Version in the file.
        found: u32,
        /// Version this build reads.
        supported: u32,
    },
    /// The file holds another kind of snapshot (header byte 12: 0 modifier only, 1 world
    /// and modifier, others for bundles written with [`save_value`]).
    #[error("the file holds a snapshot of kind {found}, not of kind {expected}")]
    WrongKind {
        /// Kind in the file.
        found: u8,
        /// Kind asked for.
        expected: u8,
    },
    /// The state cannot be encoded (e.g. a closure waveform).
    #[error("could not encode the snapshot: {0}")]
    Encode(String),
    /// The data is not a well-formed snapshot (truncated, corrupted, trailing bytes, or a
    /// parameter rejected by its constructor while decoding).
    #[error("could not decode the snapshot: {0}")]
    Decode(String),
    /// A parameter of the snapshot is rejected by its constructor.
    #[error("invalid {field} in the snapshot: {source}")]
    Param {
        /// Which part of the snapshot.
        field: &'static str,
        /// The constructor's reason.
        #[source]
        source: ParamError,
    },
    /// A value or index of the snapshot is out of range or inconsistent.
    #[error("invalid {field} in the snapshot: {reason}")]
    Invalid {
        /// Which part of the snapshot.
        field: &'static str,
        /// What is wrong.
        reason: String,
    },
}

fn invalid(field: &'static str, reason: impl Into<String>) -> SnapshotError {
    SnapshotError::Invalid {
        field,
        reason: reason.into(),
    }
}

/// A collider handle as plain data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
struct Handle {
    index: u32,
    generation: u32,
}

impl From<ColliderHandle> for Handle {
    fn from(h: ColliderHandle) -> Self {
        let (index, generation) = h.0.into_raw_parts();
        Handle { index, generation }
    }
}

impl From<Handle> for ColliderHandle {
    fn from(h: Handle) -> Self {
        ColliderHandle::from_raw_parts(h.index, h.generation)
    }
}

/// A per-pair material.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct PairEntry {
    colliders: [Handle; 2],
    material: FrictionMaterial,
}

/// One entry of a per-collider table.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct Entry<T> {
    collider: Handle,
    value: T,
}

/// A waveform; table waveforms are kept as their normalized samples, bit for bit.
#[derive(Debug, Clone)]
struct WaveformSnapshot(Waveform);

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum WaveformRepr {
    Named(Waveform),
    NormalizedTable(Vec<f64>),
}

impl Serialize for WaveformSnapshot {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match &self.0 {
            Waveform::Table(t) => WaveformRepr::NormalizedTable(t.samples().to_vec()).serialize(s),
            w => WaveformRepr::Named(w.clone()).serialize(s),
        }
    }
}

impl<'de> Deserialize<'de> for WaveformSnapshot {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match WaveformRepr::deserialize(d)? {
            WaveformRepr::Named(w) => Ok(WaveformSnapshot(w)),
            WaveformRepr::NormalizedTable(samples) => Waveform::from_normalized_table(&samples)
                .map(WaveformSnapshot)
                .map_err(serde::de::Error::custom),
        }
    }
}

/// A vibration source's parameters (its tables are rebuilt, deterministically, on restore):
/// the first component in the flat fields (the single-component format), any further ones in
/// `more`.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct VibrationSnapshot {
    direction: VibrationDirection,
    amplitude: Amplitude,
    frequency: f64,
    waveform: WaveformSnapshot,
    phase: f64,
    mode: VibrationMode,
    tangential_stiffness: Option<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    more: Vec<ComponentSnapshot>,
}

/// A further component of a vibration source.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct ComponentSnapshot {
    direction: VibrationDirection,
    amplitude: Amplitude,
    waveform: WaveformSnapshot,
    phase: f64,
}

impl From<&VibrationSource> for VibrationSnapshot {
    fn from(s: &VibrationSource) -> Self {
        VibrationSnapshot {
            direction: s.direction(),
            amplitude: s.amplitude(),
            frequency: s.frequency(),
            waveform: WaveformSnapshot(s.waveform().clone()),
            phase: s.phase(),
            mode: s.mode(),
            tangential_stiffness: s.tangential_stiffness(),
            more: s.components()[1..]
                .iter()
                .map(|c| ComponentSnapshot {
                    direction: c.direction(),
                    amplitude: c.amplitude(),
                    waveform: WaveformSnapshot(c.waveform().clone()),
                    phase: c.phase(),
                })
                .collect(),
        }
    }
}

impl VibrationSnapshot {
    fn to_source(&self) -> Result<VibrationSource, ParamError> {
        let mut components = vec![VibrationComponent::new(
            self.direction,
            self.amplitude,
            self.waveform.0.clone(),
            self.phase,
        )?];
        for c in &self.more {
            components.push(VibrationComponent::new(
                c.direction,
                c.amplitude,
                c.waveform.0.clone(),
                c.phase,
            )?);
        }
        let s = VibrationSource::superimposed(&components, self.frequency, self.mode)?;
        match self.tangential_stiffness {
            Some(k) => s.with_tangential_stiffness(k),
            None => Ok(s),
        }
    }
}

/// One contact's friction state.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct RecordSnapshot {
    /// Arena indices of the pair's colliders.
    c1: u32,
    c2: u32,
    force: [f32; 3],
    slide: f32,
    limit: f32,
    slip_speed: f32,
    inner_user_data: u32,
    mean_normal_force: f32,
    /// Parity of the step that last touched it.
    touched_odd: bool,
    regime: u8,
    /// Steps left in which the contact is still forming (0–2), or 3 while it gives under a
    /// jump in load.
    forming: u8,
    /// The warm start of the last solve (kept by rapier 0.35 builds only; 0 otherwise).
    #[serde(default)]
    warm_start_impulse: f32,
    /// The record holds the hook's next step already (absent in files of builds that never
    /// stepped ahead: false is what they meant).
    #[serde(default)]
    ahead: bool,
}

impl From<&LiveImage> for RecordSnapshot {
    fn from(l: &LiveImage) -> Self {
        let r = &l.record.state;
        RecordSnapshot {
            c1: l.c1,
            c2: l.c2,
            force: r.force,
            slide: r.slide,
            limit: r.limit,
            slip_speed: r.slip_speed,
            inner_user_data: l.record.inner_user_data,
            mean_normal_force: r.mean_normal_force,
            touched_odd: l.touched_odd,
            regime: r.regime,
            forming: r.forming,
            #[cfg(rapier_035)]
            warm_start_impulse: l.record.warm_start_impulse,
            #[cfg(not(rapier_035))]
            warm_start_impulse: 0.0,
            ahead: l.record.ahead,
        }
    }
}

/// The kernel's state of one contact (or one resisting axis pair, see [`RollingSnapshot`]).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct StateSnapshot {
    force: [f32; 3],
    slide: f32,
    limit: f32,
    slip_speed: f32,
    mean_normal_force: f32,
    regime: u8,
    forming: u8,
}

impl From<&ContactState> for StateSnapshot {
    fn from(r: &ContactState) -> Self {
        StateSnapshot {
            force: r.force,
            slide: r.slide,
            limit: r.limit,
            slip_speed: r.slip_speed,
            mean_normal_force: r.mean_normal_force,
            regime: r.regime,
            forming: r.forming,
        }
    }
}

impl StateSnapshot {
    /// The state, checked: finite, non-negative limit, slip speed and mean normal force,
    /// known regime and forming codes.
    fn to_state(self) -> Result<ContactState, SnapshotError> {
        let finite = self
            .force
            .iter()
            .chain(&[
                self.slide,
                self.limit,
                self.slip_speed,
                self.mean_normal_force,
            ])
            .all(|x| x.is_finite());
        if !finite {
            return Err(invalid("contact state", "a value is not finite"));
        }
        if !(self.limit >= 0.0 && self.slip_speed >= 0.0 && self.mean_normal_force >= 0.0) {
            return Err(invalid(
                "contact state",
                "negative friction limit, slip speed or mean normal force",
            ));
        }
        if self.forming > stickslip_core::contact::GIVING {
            return Err(invalid(
                "contact state",
                format!(
                    "forming state {} (steps left 0–2, or 3: giving)",
                    self.forming
                ),
            ));
        }
        if !matches!(
            self.regime,
            0..=2 | stickslip_core::contact::REGIME_RESET | stickslip_core::contact::REGIME_NONE
        ) {
            return Err(invalid(
                "contact state",
                format!("unknown regime code {}", self.regime),
            ));
        }
        Ok(ContactState {
            force: self.force,
            slide: self.slide,
            limit: self.limit,
            slip_speed: self.slip_speed,
            mean_normal_force: self.mean_normal_force,
            regime: self.regime,
            forming: self.forming,
        })
    }
}

impl RecordSnapshot {
    fn to_live(&self) -> Result<LiveImage, SnapshotError> {
        if !self.warm_start_impulse.is_finite() {
            return Err(invalid("contact state", "a value is not finite"));
        }
        let state = StateSnapshot {
            force: self.force,
            slide: self.slide,
            limit: self.limit,
            slip_speed: self.slip_speed,
            mean_normal_force: self.mean_normal_force,
            regime: self.regime,
            forming: self.forming,
        }
        .to_state()?;
        Ok(LiveImage {
            c1: self.c1,
            c2: self.c2,
            touched_odd: self.touched_odd,
            record: ContactRecord {
                state,
                inner_user_data: self.inner_user_data,
                ahead: self.ahead,
                #[cfg(rapier_035)]
                warm_start_impulse: self.warm_start_impulse,
            },
        })
    }
}

/// One slot of the contact store: its generation (part of the `user_data` rapier's manifolds
/// hold), and the record while it is live (a free slot's old record is never read again).
#[derive(Debug, Clone, Serialize, Deserialize)]
struct SlotSnapshot {
    generation: u8,
    record: Option<RecordSnapshot>,
}

/// An entry of the store's key map (collider pair and which manifold → slot).
#[derive(Debug, Clone, Serialize, Deserialize)]
struct KeySnapshot {
    c1: Handle,
    c2: Handle,
    part: PartSnapshot,
    slot: u32,
}

/// Which manifold of a pair (`contact_store::ManifoldPart`).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
enum PartSnapshot {
    Whole,
    Subshapes(u32, u32),
    Cluster([i8; 3]),
}

impl From<ManifoldPart> for PartSnapshot {
    fn from(p: ManifoldPart) -> Self {
        match p {
            ManifoldPart::Whole => PartSnapshot::Whole,
            ManifoldPart::Subshapes(a, b) => PartSnapshot::Subshapes(a, b),
            ManifoldPart::Cluster(n) => PartSnapshot::Cluster(n),
        }
    }
}

impl From<PartSnapshot> for ManifoldPart {
    fn from(p: PartSnapshot) -> Self {
        match p {
            PartSnapshot::Whole => ManifoldPart::Whole,
            PartSnapshot::Subshapes(a, b) => ManifoldPart::Subshapes(a, b),
            PartSnapshot::Cluster(n) => ManifoldPart::Cluster(n),
        }
    }
}

/// The contact store, exactly: slots in order (free ones are taken lowest first), the key
/// map, and the generation of the next slot to be added.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct ContactsSnapshot {
    slots: Vec<SlotSnapshot>,
    keys: Vec<KeySnapshot>,
    next_generation: u8,
    /// Records created since the last sweep (the next sweep may come early: churn).
    created: u32,
}

impl From<&ContactStore> for ContactsSnapshot {
    fn from(store: &ContactStore) -> Self {
        let image = store.image();
        ContactsSnapshot {
            slots: image
                .slots
                .iter()
                .map(|s| SlotSnapshot {
                    generation: s.generation,
                    record: s.live.as_ref().map(RecordSnapshot::from),
                })
                .collect(),
            keys: image
                .keys
                .iter()
                .map(|(k, slot)| KeySnapshot {
                    c1: k.c1.into(),
                    c2: k.c2.into(),
                    part: k.part.into(),
                    slot: *slot,
                })
                .collect(),
            next_generation: image.next_generation,
            created: image.created,
        }
    }
}

impl ContactsSnapshot {
    fn to_store(&self) -> Result<ContactStore, SnapshotError> {
        // Encoded user_data holds slot index + 1 in INDEX_BITS bits.
        let n = self.slots.len();
        if n >= (1usize << INDEX_BITS) {
            return Err(invalid("contact store", format!("{n} slots")));
        }
        let mut slots = Vec::with_capacity(n);
        for s in &self.slots {
            slots.push(SlotImage {
                generation: s.generation,
                live: s.record.as_ref().map(|r| r.to_live()).transpose()?,
            });
        }
        let image = StoreImage {
            slots,
            keys: self
                .keys
                .iter()
                .map(|k| {
                    (
                        ContactKey {
                            c1: k.c1.into(),
                            c2: k.c2.into(),
                            part: k.part.into(),
                        },
                        k.slot,
                    )
                })
                .collect(),
            next_generation: self.next_generation,
            created: self.created,
        };
        ContactStore::from_image(&image).map_err(|e| invalid("contact store", e))
    }
}

/// The step clock.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct ClockSnapshot {
    time: f64,
    dt: f64,
    step: u32,
    sweeps: u32,
}

/// World totals of the last step.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct TotalsSnapshot {
    contacts: u64,
    sticking: u64,
    stick_slip: u64,
    sliding: u64,
    normal_force: f64,
    friction_force: f64,
    dissipated_power: f64,
    dissipated_energy: f64,
    reset: u64,
}

/// A report of the last step.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct ReportSnapshot {
    collider1: Handle,
    collider2: Handle,
    point: [f32; crate::report::DIM],
    normal: [f32; crate::report::DIM],
    regime: Regime,
    mu: f64,
    limit: f64,
    normal_force: f64,
    friction_force: [f32; crate::report::DIM],
    slip_velocity: [f32; crate::report::DIM],
    dissipated_power: f64,
    reset: bool,
}

impl From<&ContactReport> for ReportSnapshot {
    fn from(r: &ContactReport) -> Self {
        ReportSnapshot {
            collider1: r.collider1.into(),
            collider2: r.collider2.into(),
            point: r.point,
            normal: r.normal,
            regime: r.regime,
            mu: r.mu,
            limit: r.limit,
            normal_force: r.normal_force,
            friction_force: r.friction_force,
            slip_velocity: r.slip_velocity,
            dissipated_power: r.dissipated_power,
            reset: r.reset,
        }
    }
}

impl ReportSnapshot {
    fn to_report(self) -> Result<ContactReport, SnapshotError> {
        let finite = self
            .point
            .iter()
            .chain(&self.normal)
            .chain(&self.friction_force)
            .chain(&self.slip_velocity)
            .all(|x| x.is_finite())
            && [
                self.mu,
                self.limit,
                self.normal_force,
                self.dissipated_power,
            ]
            .iter()
            .all(|x| x.is_finite());
        if !finite {
            return Err(invalid("contact report", "a value is not finite"));
        }
        let mut r = ContactReport::new(self.collider1.into(), self.collider2.into());
        r.point = self.point;
        r.normal = self.normal;
        r.regime = self.regime;
        r.mu = self.mu;
        r.limit = self.limit;
        r.normal_force = self.normal_force;
        r.friction_force = self.friction_force;
        r.slip_velocity = self.slip_velocity;
        r.dissipated_power = self.dissipated_power;
        r.reset = self.reset;
        Ok(r)
    }
}

/// Everything a [`StickSlip`] modifier keeps except the user's wrapped hooks: take one with
/// [`StickSlip::snapshot`], turn it back into a modifier with [`StickSlip::restore`], and
/// store it with serde (or [`StickSlipSnapshot::save`]/[`StickSlipSnapshot::load`], or
/// bundled with rapier's world in a [`WorldSnapshot`]). See the [module docs](self).
///
/// The contents are private: the snapshot is only meant to be restored. A deserialized
/// snapshot is validated by [`StickSlip::restore`].
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StickSlipSnapshot {
    config: StickSlipConfig,
    default_material: FrictionMaterial,
    materials: Vec<Entry<FrictionMaterial>>,
    vibrations: Vec<Entry<VibrationSnapshot>>,
    /// Surface velocities (m/s, x y z; z = 0 in 2D).
    #[serde(default)]
    surfaces: Vec<Entry<[f32; 3]>>,
    /// Arena indices of the colliders whose hook flag the modifier turned on.
    flagged: Vec<u32>,
    /// Arena indices of the attached colliders.
    attached: Vec<u32>,
    /// Per-pair materials.
    pair_materials: Vec<PairEntry>,
    contacts: ContactsSnapshot,
    clock: ClockSnapshot,
    totals: TotalsSnapshot,
    read_back: ReadBack,
    reports: Vec<ReportSnapshot>,
    /// Colliders whose hook flag is off because their contacts are quiet, with the pose
    /// their drift is measured from (see `recycle`).
    #[serde(default)]
    quiet: Vec<QuietEntry>,
    /// Arena indices of the colliders to hook again at the next step.
    #[serde(default)]
    wake: Vec<u32>,
    /// Every quiet collider is to be hooked again at the next step.
    #[serde(default)]
    wake_all: bool,
    /// What the last `end_step` measured for composite contact patches: their next step
    /// reads it (rapier rebuilds a clustered manifold every step, so its points cannot tell).
    #[serde(default)]
    patches: Vec<PatchSnapshot>,
    /// Rolling and spinning resistance (absent in files of builds that did not keep it: the
    /// restored world's resisting joints are then replaced, their states starting afresh).
    #[serde(default)]
    rolling: RollingSnapshot,
}

/// The pairs resisting rolling or spinning (see `rolling`) and the resistance's step count.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
struct RollingSnapshot {
    step: u64,
    /// The last step's length (s) (the torques of the reports).
    #[serde(default)]
    dt: f64,
    pairs: Vec<ResistingSnapshot>,
}

/// One resisting pair: its joint in the world (arena index and generation), its rolling and
/// spinning states, the axes and arms of its last step (vectors x y z, z = 0 in 2D).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct ResistingSnapshot {
    colliders: [Handle; 2],
    joint: [u32; 2],
    roll: StateSnapshot,
    spin: StateSnapshot,
    axis_x: [f32; 3],
    normal: [f32; 3],
    arm_roll: f32,
    arm_spin: f32,
    seen: u64,
    /// The contact point (m) and normal force (N) of the last step.
    #[serde(default)]
    point: [f32; 3],
    #[serde(default)]
    normal_force: f64,
    /// Whether the materials resisted rolling and spinning in the last step.
    #[serde(default)]
    resists: [bool; 2],
    /// The solver's substeps in the last step.
    #[serde(default)]
    substeps: u32,
}

impl From<&ResistingPair> for ResistingSnapshot {
    fn from(((c1, c2), r): &ResistingPair) -> Self {
        let (index, generation) = r.joint.into_raw_parts();
        ResistingSnapshot {
            colliders: [(*c1).into(), (*c2).into()],
            joint: [index, generation],
            roll: (&r.roll).into(),
            spin: (&r.spin).into(),
            axis_x: crate::tangent::world(r.axis_x),
            normal: crate::tangent::world(r.normal),
            arm_roll: r.arm_roll,
            arm_spin: r.arm_spin,
            seen: r.seen,
            point: crate::tangent::world(r.point),
            normal_force: r.normal_force,
            resists: r.resists,
            substeps: u32::try_from(r.substeps).unwrap_or(u32::MAX),
        }
    }
}

impl ResistingSnapshot {
    /// The pair, checked (finite axes, arms, point and load; valid states).
    fn to_pair(self) -> Result<ResistingPair, SnapshotError> {
        let finite = self
            .axis_x
            .iter()
            .chain(&self.normal)
            .chain(&self.point)
            .chain(&[self.arm_roll, self.arm_spin])
            .all(|x| x.is_finite())
            && self.normal_force.is_finite();
        if !finite {
            return Err(invalid("rolling resistance", "a value is not finite"));
        }
        let [index, generation] = self.joint;
        Ok((
            (self.colliders[0].into(), self.colliders[1].into()),
            Resisting {
                joint: ImpulseJointHandle::from_raw_parts(index, generation),
                roll: self.roll.to_state()?,
                spin: self.spin.to_state()?,
                axis_x: crate::tangent::vector(self.axis_x),
                normal: crate::tangent::vector(self.normal),
                arm_roll: self.arm_roll,
                arm_spin: self.arm_spin,
                seen: self.seen,
                point: crate::tangent::vector(self.point),
                normal_force: self.normal_force,
                resists: self.resists,
                substeps: (self.substeps as usize).max(1),
            },
        ))
    }
}

/// A quiet collider and the pose its drift is measured from.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct QuietEntry {
    /// The collider's arena index and the low 8 bits of its generation (what the modifier
    /// keeps of it).
    collider: Handle,
    translation: [f32; 3],
    /// The rotation as the modifier keeps it: in 3D the unit quaternion packed into 64 bits
    /// (its largest component dropped, the others as 20-bit multiples of 2⁻¹⁹), in 2D the
    /// unit complex's f32 bits.
    rotation: [u32; 2],
    /// bfloat16 bits of the collider's reach (m).
    reach: u16,
}

/// The last solve of a composite contact patch, by the `user_data` of its record.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
struct PatchSnapshot {
    user_data: u32,
    normal_force: f64,
    mu: [f32; 3],
    warm_start_impulse: f64,
}

impl StickSlipSnapshot {
    /// Simulated time (s) at the snapshot.
    pub fn time(&self) -> f64 {
        self.clock.time
    }

    /// Number of contacts with friction state at the snapshot.
    pub fn active_contacts(&self) -> usize {
        self.contacts
            .slots
            .iter()
            .filter(|s| s.record.is_some())
            .count()
    }

    /// Writes the snapshot (header and CBOR, see the [module docs](self)) to `writer`.
    pub fn save<W: Write>(&self, writer: W) -> Result<(), SnapshotError> {
        write_framed(writer, KIND_MODIFIER, self)
    }

    /// Reads a snapshot written by [`Self::save`]; [`StickSlip::restore`] validates it.
    pub fn load<R: Read>(reader: R) -> Result<Self, SnapshotError> {
        read_framed(reader, KIND_MODIFIER)
    }
}

/// The colliders of `indices` (increasing arena indices) that are in `colliders`.
fn restore_bits(
    field: &'static str,
    indices: &[u32],
    colliders: &ColliderSet,
) -> Result<ColliderBits, SnapshotError> {
    let mut bits = ColliderBits::default();
    for (k, &i) in indices.iter().enumerate() {
        if k > 0 && indices[k - 1] >= i {
            return Err(invalid(field, "indices not increasing"));
        }
        // Only colliders of the set size the bit set; others can never be stepped.
        if let Some((_, handle)) = colliders.get_unknown_gen(i) {
            bits.set(handle, true);
        }
    }
    Ok(bits)
}

/// Entries of `entries` whose collider is in `colliders`, in a fresh map; entries must come
/// in increasing collider order (as [`StickSlip::snapshot`] writes them).
fn restore_map<T, U>(
    field: &'static str,
    entries: &[Entry<T>],
    colliders: &ColliderSet,
    mut convert: impl FnMut(&T) -> Result<U, SnapshotError>,
) -> Result<ColliderMap<U>, SnapshotError> {
    let mut map = ColliderMap::default();
    for (i, e) in entries.iter().enumerate() {
        if i > 0 && entries[i - 1].collider.index >= e.collider.index {
            return Err(invalid(field, "entries not in increasing collider order"));
        }
        let value = convert(&e.value)?;
        let handle = ColliderHandle::from(e.collider);
        // Only colliders of the set size the dense map; others can never be stepped.
        if colliders.contains(handle) {
            map.insert(handle, value);
        }
    }
    Ok(map)
}

impl<H> StickSlip<H> {
    /// A snapshot of the modifier's whole state except the wrapped hooks (see
    /// [`StickSlipSnapshot`]). Take it between steps (after [`StickSlip::end_step`]).
    pub fn snapshot(&self) -> StickSlipSnapshot {
        let t = &self.totals;
        StickSlipSnapshot {
            config: self.config,
            default_material: self.laws.default_material().clone(),
            materials: self
                .laws
                .materials()
                .map(|(h, m)| Entry {
                    collider: h.into(),
                    value: m.clone(),
                })
                .collect(),
            vibrations: self
                .vibrations
                .iter()
                .map(|(h, s)| Entry {
                    collider: h.into(),
                    value: s.into(),
                })
                .collect(),
            surfaces: self
                .surfaces
                .iter()
                .map(|(h, v)| Entry {
                    collider: h.into(),
                    value: crate::tangent::world(*v),
                })
                .collect(),
            flagged: self.flagged.indices().collect(),
            attached: self.attached.indices().collect(),
            pair_materials: {
                let mut pairs: Vec<PairEntry> = self
                    .laws
                    .pairs()
                    .map(|((a, b), m)| PairEntry {
                        colliders: [a.into(), b.into()],
                        material: m.clone(),
                    })
                    .collect();
                // The map's order never matters; sorted, equal states give equal snapshots.
                pairs.sort_by_key(|p| p.colliders.map(|h| (h.index, h.generation)));
                pairs
            },
            contacts: (&self.store).into(),
            clock: ClockSnapshot {
                time: self.clock.time,
                dt: self.clock.dt,
                step: self.clock.step,
                sweeps: self.clock.sweeps,
            },
            totals: TotalsSnapshot {
                contacts: t.contacts as u64,
                sticking: t.sticking as u64,
                stick_slip: t.stick_slip as u64,
                sliding: t.sliding as u64,
                normal_force: t.normal_force,
                friction_force: t.friction_force,
                dissipated_power: t.dissipated_power,
                dissipated_energy: t.dissipated_energy,
                reset: t.reset as u64,
            },
            read_back: self.read_back,
            reports: self.reports.iter().map(ReportSnapshot::from).collect(),
            quiet: self
                .recycling
                .poses
                .iter()
                .filter(|&(i, g, _)| {
                    let h = ColliderHandle::from_raw_parts(i, g as u32);
                    self.recycling.quiet.contains(h)
                })
                .map(|(index, generation, q)| {
                    let (translation, rotation, reach) = q.stored();
                    QuietEntry {
                        collider: Handle {
                            index,
                            generation: generation as u32,
                        },
                        translation,
                        rotation,
                        reach,
                    }
                })
                .collect(),
            wake: self.recycling.wake.indices().collect(),
            wake_all: self.recycling.wake_all,
            patches: {
                let mut patches: Vec<PatchSnapshot> = self
                    .patches_measured
                    .iter()
                    .map(|(user_data, m)| PatchSnapshot {
                        user_data,
                        normal_force: m.normal_force,
                        mu: crate::tangent::world(m.mu),
                        warm_start_impulse: m.warm_start_impulse,
                    })
                    .collect();
                // Sealed by every `end_step`, so already in order; sorted all the same, as the
                // restore requires.
                patches.sort_by_key(|p| p.user_data);
                patches
            },
            rolling: {
                let (step, images) = self.rolling.images();
                RollingSnapshot {
                    step,
                    dt: self.rolling.dt,
                    pairs: images.iter().map(ResistingSnapshot::from).collect(),
                }
            },
        }
    }

    /// The modifier `snapshot` was taken of, wrapping the hooks `inner` (hooks are code, not
    /// data: pass the same ones, in the same state, for a bit-identical resume).
    ///
    /// `colliders` is the collider set of the world it will step (the restored rapier
    /// world's): per-collider materials, vibration sources and hook flags of colliders that
    /// are not in it are dropped (no step could reach them), and nothing is allocated by a
    /// handle that is not in it. Every parameter and index is validated first (see the
    /// [module docs](self)).
    pub fn restore(
        snapshot: &StickSlipSnapshot,
        colliders: &ColliderSet,
        inner: H,
    ) -> Result<Self, SnapshotError> {
        let s = snapshot;
        s.config.validate().map_err(|source| SnapshotError::Param {
            field: "config",
            source,
        })?;
        let materials = restore_map("materials", &s.materials, colliders, |m| Ok(m.clone()))?;
        let vibrations = restore_map("vibration sources", &s.vibrations, colliders, |v| {
            v.to_source().map_err(|source| SnapshotError::Param {
                field: "vibration source",
                source,
            })
        })?;
        let surfaces = restore_map("surface velocities", &s.surfaces, colliders, |v| {
            if v.iter().all(|x| x.is_finite()) {
                Ok(crate::tangent::vector(*v))
            } else {
                Err(invalid("surface velocities", "a value is not finite"))
            }
        })?;
        let flagged = restore_bits("hook flags", &s.flagged, colliders)?;
        let attached = restore_bits("attached colliders", &s.attached, colliders)?;
        let store = s.contacts.to_store()?;
        let c = s.clock;
        if !(c.time.is_finite() && c.dt.is_finite() && c.dt >= 0.0) {
            return Err(invalid("clock", "time or dt not finite, or dt negative"));
        }
        let t = s.totals;
        let count = |n: u64| {
            usize::try_from(n).map_err(|_| invalid("totals", format!("count {n} too large")))
        };
        let totals = WorldTotals {
            contacts: count(t.contacts)?,
            sticking: count(t.sticking)?,
            stick_slip: count(t.stick_slip)?,
            sliding: count(t.sliding)?,
            normal_force: t.normal_force,
            friction_force: t.friction_force,
            dissipated_power: t.dissipated_power,
            dissipated_energy: t.dissipated_energy,
            reset: count(t.reset)?,
        };
        let forces = [
            totals.normal_force,
            totals.friction_force,
            totals.dissipated_power,
            totals.dissipated_energy,
        ];
        if !forces.iter().all(|x| x.is_finite()) {
            return Err(invalid("totals", "a value is not finite"));
        }
        let reports = s
            .reports
            .iter()
            .map(|r| r.to_report())
            .collect::<Result<Vec<_>, _>>()?;
        let mut m = StickSlip::with_hooks(s.default_material.clone(), inner);
        for (h, material) in materials.iter() {
            m.set_material(h, material.clone());
        }
        for p in &s.pair_materials {
            let [a, b] = p.colliders.map(ColliderHandle::from);
            if colliders.contains(a) && colliders.contains(b) {
                m.set_pair_material(a, b, p.material.clone());
            }
        }
        m.config = s.config;
        m.attached = attached;
        m.vibrations = vibrations;
        m.surfaces = surfaces;
        m.flagged = flagged;
        m.store = store;
        m.clock = Clock {
            time: c.time,
            dt: c.dt,
            step: c.step,
            // Set from the integration parameters by every begin_step.
            clustering: true,
            sweeps: c.sweeps,
            open: false,
        };
        m.read_back = s.read_back;
        m.reports = reports;
        m.totals = totals;
        for (k, q) in s.quiet.iter().enumerate() {
            if k > 0 && s.quiet[k - 1].collider.index >= q.collider.index {
                return Err(invalid(
                    "quiet colliders",
                    "not in increasing collider order",
                ));
            }
            let pose = crate::quiet::QuietPose::from_stored(q.translation, q.rotation, q.reach);
            let Some(pose) = pose else {
                return Err(invalid(
                    "quiet colliders",
                    "a pose is not finite or its rotation not a unit one",
                ));
            };
            if q.collider.generation > u8::MAX as u32 {
                return Err(invalid("quiet colliders", "a generation beyond 8 bits"));
            }
            // The live collider at the index, if its generation's low bits are the pose's.
            let live = colliders
                .get_unknown_gen(q.collider.index)
                .map(|(_, h)| h)
                .filter(|h| h.0.into_raw_parts().1 & 0xFF == q.collider.generation);
            if let Some(h) = live
                && m.flagged.contains(h)
                && m.attached.contains(h)
            {
                m.recycling.quiet.set(h, true);
                m.recycling.active.cover(h);
                m.recycling.poses.insert(h, pose);
            }
        }
        let attached_ids: Vec<u32> = m.attached.indices().collect();
        for i in attached_ids {
            if let Some((_, h)) = colliders.get_unknown_gen(i) {
                m.recycling.active.cover(h);
            }
        }
        m.recycling.wake = restore_bits("colliders to wake", &s.wake, colliders)?;
        m.recycling.wake_all = s.wake_all;
        for (k, p) in s.patches.iter().enumerate() {
            if k > 0 && s.patches[k - 1].user_data >= p.user_data {
                return Err(invalid("contact patches", "not in increasing order"));
            }
            let finite = p.normal_force.is_finite()
                && p.warm_start_impulse.is_finite()
                && p.mu.iter().all(|v| v.is_finite());
            if !finite {
                return Err(invalid("contact patches", "a value is not finite"));
            }
            m.patches_measured.insert(
                p.user_data,
                Measured {
                    normal_force: p.normal_force,
                    mu: crate::tangent::vector(p.mu),
                    warm_start_impulse: p.warm_start_impulse,
                },
            );
        }
        m.patches_measured.seal();
        let mut resisting = Vec::new();
        for (k, p) in s.rolling.pairs.iter().enumerate() {
            if k > 0 && s.rolling.pairs[k - 1].colliders >= p.colliders {
                return Err(invalid(
                    "rolling resistance",
                    "pairs not in increasing collider order",
                ));
            }
            let (pair, r) = p.to_pair()?;
            if r.seen > s.rolling.step {
                return Err(invalid(
                    "rolling resistance",
                    "a pair seen after the resistance's last step",
                ));
            }
            // Only pairs of colliders in the set: others can never be stepped.
            if colliders.contains(pair.0) && colliders.contains(pair.1) {
                resisting.push((pair, r));
            }
        }
        if !(s.rolling.dt.is_finite() && s.rolling.dt >= 0.0) {
            return Err(invalid("rolling resistance", "dt not finite, or negative"));
        }
        m.rolling = crate::rolling::Rolling::from_images(s.rolling.step, s.rolling.dt, resisting);
        // Combined laws are computed again.
        Ok(m)
    }
}

/// rapier's world and the stickslip modifier's state together: what a saved simulation
/// needs to resume. Write one with [`WorldSnapshot::save_from`] (from a live world) or
/// [`WorldSnapshot::save`], read it with [`WorldSnapshot::load`] and resume with
/// [`WorldSnapshot::restore`]. See the [module docs](self).
#[derive(Serialize, Deserialize)]
pub struct WorldSnapshot {
    /// rapier's world (its `serde-serialize` form: bodies, colliders, joints, narrow and
    /// broad phase, islands, integration parameters, gravity).
    pub world: PhysicsWorld,
    /// The modifier's state.
    pub friction: StickSlipSnapshot,
}

/// [`WorldSnapshot`] by reference, for saving a live world without copying it.
#[derive(Serialize)]
struct WorldSnapshotRef<'a> {
    world: &'a PhysicsWorld,
    friction: StickSlipSnapshot,
}

impl WorldSnapshot {
    /// Writes `world` and `friction`'s state to `writer` (header and CBOR, see the
    /// [module docs](self)). Call between steps.
    pub fn save_from<H, W: Write>(
        world: &PhysicsWorld,
        friction: &StickSlip<H>,
        writer: W,
    ) -> Result<(), SnapshotError> {
        let bundle = WorldSnapshotRef {
            world,
            friction: friction.snapshot(),
        };
        write_framed(writer, KIND_WORLD, &bundle)
    }

    /// Writes this snapshot to `writer`.
    pub fn save<W: Write>(&self, writer: W) -> Result<(), SnapshotError> {
        write_framed(writer, KIND_WORLD, self)
    }

    /// Reads a snapshot written by [`Self::save_from`] or [`Self::save`] (the reader is
    /// buffered inside). The modifier's part is validated by [`Self::restore`].
    pub fn load<R: Read>(reader: R) -> Result<Self, SnapshotError> {
        read_framed(reader, KIND_WORLD)
    }

    /// The rapier world and the modifier, wrapping your hooks `inner`, ready to step on.
    pub fn restore<H>(self, inner: H) -> Result<(PhysicsWorld, StickSlip<H>), SnapshotError> {
        let friction = StickSlip::restore(&self.friction, &self.world.colliders, inner)?;
        Ok((self.world, friction))
    }
}

/// Writes `value` in the snapshot format with header kind `kind`: for bundles of your own
/// around a world and a [`StickSlipSnapshot`] (e.g. a runner's counters beside them). Kinds
/// [`KIND_MODIFIER`] and [`KIND_WORLD`] are this module's; pick another one.
#[doc(hidden)]
pub fn save_value<T: Serialize, W: Write>(
    writer: W,
    kind: u8,
    value: &T,
) -> Result<(), SnapshotError> {
    write_framed(writer, kind, value)
}

/// Reads a value written by [`save_value`] with the same `kind` (header checked, decoding
/// errors and panics inside deserializers returned as errors, trailing bytes rejected).
/// Validate what you read: [`StickSlip::restore`] does for the modifier's part.
#[doc(hidden)]
pub fn load_value<T: serde::de::DeserializeOwned, R: Read>(
    reader: R,
    kind: u8,
) -> Result<T, SnapshotError> {
    read_framed(reader, kind)
}

fn write_framed<T: Serialize, W: Write>(
    writer: W,
    kind: u8,
    value: &T,
) -> Result<(), SnapshotError> {
    let mut w = std::io::BufWriter::new(writer);
    w.write_all(&MAGIC)?;
    w.write_all(&FORMAT_VERSION.to_le_bytes())?;
    w.write_all(&[kind])?;
    ciborium::into_writer(value, &mut w).map_err(|e| match e {
        ciborium::ser::Error::Io(e) => SnapshotError::Io(e),
        ciborium::ser::Error::Value(msg) => SnapshotError::Encode(msg),
    })?;
    w.flush()?;
    Ok(())
}

fn read_framed<T: serde::de::DeserializeOwned, R: Read>(
    reader: R,
    kind: u8,
) -> Result<T, SnapshotError> {
    let mut r = std::io::BufReader::new(reader);
    let mut header = [0u8; 13];
    r.read_exact(&mut header).map_err(|e| match e.kind() {
        std::io::ErrorKind::UnexpectedEof => SnapshotError::NotASnapshot,
        _ => SnapshotError::Io(e),
    })?;
    if header[..8] != MAGIC {
        return Err(SnapshotError::NotASnapshot);
    }
    let version = u32::from_le_bytes([header[8], header[9], header[10], header[11]]);
    if version != FORMAT_VERSION {
        return Err(SnapshotError::UnsupportedVersion {
            found: version,
            supported: FORMAT_VERSION,
        });
    }
    if header[12] != kind {
        return Err(SnapshotError::WrongKind {
            found: header[12],
            expected: kind,
        });
    }
    // rapier's and serde's deserializers are not ours: a panic inside one is a decode error.
    let decoded = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        ciborium::from_reader::<T, _>(&mut r)
    }))
    .map_err(|_| SnapshotError::Decode("the decoder panicked".into()))?;
    let value = decoded.map_err(|e| match e {
        ciborium::de::Error::Io(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => {
            SnapshotError::Decode("truncated".into())
        }
        ciborium::de::Error::Io(e) => SnapshotError::Io(e),
        e => SnapshotError::Decode(e.to_string()),
    })?;
    let mut rest = [0u8; 1];
    if r.read(&mut rest)? != 0 {
        return Err(SnapshotError::Decode(
            "trailing bytes after the snapshot".into(),
        ));
    }
    Ok(value)
}
