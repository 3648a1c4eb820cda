//! # stickslip-rerun
//!
//! Streams a rapier world with the stickslip contact modifier to [rerun](https://rerun.io):
//! body poses and shapes, contact points colored by friction regime (sticking / stick-slip /
//! sliding), friction force arrows, per-contact, per-body and world series (friction state μ,
//! slip speed, normal force, effective μ, dissipated power) and the signals of vibration
//! sources, on the timelines `step` and `sim_time`. Every entity path is listed in [`paths`].
//!
//! Sinks ([`Sink`]): an `.rrd` file, a live viewer over gRPC (`rerun` listening, default
//! `rerun+http://127.0.0.1:9876/proxy`), or memory (tests).
//!
//! ```
//! use rapier3d::prelude::*;
//! use stickslip_core::law::{Coulomb, Law};
//! use stickslip_rapier::{FrictionMaterial, StickSlip};
//! use stickslip_rerun::{LogOptions, RerunLogger, Sink};
//!
//! let mut world = PhysicsWorld::default();
//! let ground = world.insert_body(RigidBodyBuilder::fixed());
//! let ground_collider = world.insert_collider(ColliderBuilder::cuboid(5.0, 0.1, 5.0), Some(ground));
//! let (cube, _) = world.insert(
//!     RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.35, 0.0)),
//!     ColliderBuilder::cuboid(0.25, 0.25, 0.25),
//! );
//! let mut friction = StickSlip::new(FrictionMaterial::new(Law::Coulomb(Coulomb::new(0.5).unwrap())));
//! friction.attach(&mut world.colliders, ground_collider, None);
//!
//! let (rec, memory) = stickslip_rerun::open("doc-example", &Sink::Memory).unwrap();
//! let mut logger = RerunLogger::new(rec, LogOptions::default());
//! logger.set_body_name(cube, "cube");
//! for step in 1..=10 {
//!     friction.step(&mut world);
//!     logger.log_step(step, &world, &friction).unwrap();
//! }
//! logger.flush().unwrap();
//! assert_eq!(logger.logged_steps(), 10);
//! assert!(memory.unwrap().num_msgs() > 0);
//! ```
#![warn(missing_docs)]

pub mod inspect;
pub mod layout;
pub mod paths;
pub mod prelude;

use rapier3d::prelude::*;
use rerun::{
    AnnotationContext, Arrows3D, Boxes3D, Capsules3D, Color, Ellipsoids3D, FillMode, Mesh3D,
    Points3D, Quaternion, RecordingStream, RecordingStreamBuilder, Scalars, SeriesLines,
    Transform3D, ViewCoordinates,
};
use std::collections::{HashMap, HashSet};
use std::path::PathBuf;
use stickslip_core::law::Regime;
use stickslip_rapier::{ContactReport, RollingReport, StickSlip};

pub use rerun::sink::MemorySinkStorage;

/// Where a recording goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Sink {
    /// Write an `.rrd` file.
    File(PathBuf),
    /// Stream to a viewer over gRPC: `None` is the local default viewer
    /// (`rerun+http://127.0.0.1:9876/proxy`), or a URL like that, or `HOST:PORT`.
    Grpc(Option<String>),
    /// Keep the messages in memory (tests).
    Memory,
}

/// What can go wrong while logging.
#[derive(Debug, thiserror::Error)]
pub enum LogError {
    /// The recording stream could not be created (file not writable, bad URL, …).
    #[error("cannot open the rerun recording: {0}")]
    Open(#[from] rerun::RecordingStreamError),
    /// The sinks cannot be set up.
    #[error("cannot set up the rerun sinks: {0}")]
    Sinks(String),
    /// No viewer accepts connections at a live stream's address (rerun's gRPC sink would
    /// buffer and retry silently).
    #[error(
        "no rerun viewer is listening at {url} ({reason}); start one with `rerun`, or pass \
         its address with --connect HOST:PORT"
    )]
    Unreachable {
        /// The gRPC URL.
        url: String,
        /// What the connection attempt said.
        reason: String,
    },
    /// Flushing the sink failed (disk full, viewer gone, …).
    #[error("rerun sink failed to flush: {0}")]
    Flush(String),
}

/// The gRPC URL for a `--connect` argument: `None` → the local viewer; `HOST:PORT` →
/// `rerun+http://HOST:PORT/proxy`; anything with a scheme is taken as is.
pub fn grpc_url(addr: Option<&str>) -> String {
    match addr {
        None => format!(
            "rerun+http://127.0.0.1:{}/proxy",
            rerun::DEFAULT_SERVER_PORT
        ),
        Some(a) if a.contains("://") => a.to_string(),
        Some(a) => format!("rerun+http://{a}/proxy"),
    }
}

/// Checks that something accepts TCP connections at the gRPC address of `--connect ADDR`
/// (see [`grpc_url`]) within `timeout`: rerun's gRPC sink never fails on an address where
/// nobody listens, it buffers and retries, so a live stream to a mistyped address would run
/// silently into nothing.
pub fn check_reachable(addr: Option<&str>, timeout: std::time::Duration) -> Result<(), LogError> {
    use std::net::{TcpStream, ToSocketAddrs};
    let url = grpc_url(addr);
    let unreachable = |reason: String| LogError::Unreachable {
        url: url.clone(),
        reason,
    };
    // scheme://HOST:PORT/path → HOST:PORT
    let authority = url
        .split_once("://")
        .map_or(url.as_str(), |(_, rest)| rest)
        .split('/')
        .next()
        .unwrap_or_default();
    let targets = authority
        .to_socket_addrs()
        .map_err(|e| unreachable(format!("cannot resolve `{authority}`: {e}")))?;
    let mut last = format!("`{authority}` resolves to no address");
    for target in targets {
        match TcpStream::connect_timeout(&target, timeout) {
            Ok(_) => return Ok(()),
            Err(e) => last = format!("{target}: {e}"),
        }
    }
    Err(unreachable(last))
}

/// Opens a recording stream for `app_id` on `sink`, with the automatic `log_time` timeline
/// off. The memory storage is returned for [`Sink::Memory`].
pub fn open(
    app_id: &str,
    sink: &Sink,
) -> Result<(RecordingStream, Option<MemorySinkStorage>), LogError> {
    open_all(app_id, std::slice::from_ref(sink))
}

/// Like [`open`] with several sinks at once (e.g. an `.rrd` file and a live viewer).
/// [`Sink::Memory`] cannot be combined with others.
pub fn open_all(
    app_id: &str,
    sinks: &[Sink],
) -> Result<(RecordingStream, Option<MemorySinkStorage>), LogError> {
    let id = rerun::ApplicationId::try_new(app_id)
        .map_err(|e| LogError::Sinks(format!("invalid application id `{app_id}`: {e}")))?;
    let builder = RecordingStreamBuilder::new(id);
    let (rec, memory) = match sinks {
        [] => return Err(LogError::Sinks("no sink given".into())),
        [Sink::File(path)] => (builder.save(path)?, None),
        [Sink::Grpc(addr)] => (builder.connect_grpc_opts(grpc_url(addr.as_deref()))?, None),
        [Sink::Memory] => {
            let (rec, storage) = builder.memory()?;
            (rec, Some(storage))
        }
        many => {
            let mut out: Vec<Box<dyn rerun::sink::LogSink>> = Vec::new();
            for s in many {
                match s {
                    Sink::File(path) => out
                        .push(Box::new(rerun::sink::FileSink::new(path).map_err(|e| {
                            LogError::Sinks(format!("{}: {e}", path.display()))
                        })?)),
                    Sink::Grpc(addr) => {
                        let url = grpc_url(addr.as_deref());
                        let uri = match url.parse() {
                            Ok(rerun::external::re_uri::RedapUri::Proxy(uri)) => uri,
                            _ => {
                                return Err(LogError::Sinks(format!(
                                    "`{url}` is not a rerun proxy URL"
                                )));
                            }
                        };
                        out.push(Box::new(rerun::sink::GrpcSink::new(uri)));
                    }
                    Sink::Memory => {
                        return Err(LogError::Sinks(
                            "the memory sink cannot be combined with others".into(),
                        ));
                    }
                }
            }
            (builder.set_sinks(out)?, None)
        }
    };
    rec.set_log_time_enabled(false);
    rec.set_log_tick_enabled(false);
    Ok((rec, memory))
}

/// Logging options.
#[derive(Debug, Clone, PartialEq)]
pub struct LogOptions {
    /// [`RerunLogger::log_step`] logs only steps that are multiples of this (≥ 1).
    pub every: u64,
    /// Per-contact series for at most this many contacts (the first ones seen).
    pub max_contact_series: usize,
    /// Per-body series for at most this many non-fixed bodies (the first ones seen).
    pub max_body_series: usize,
    /// Length of friction arrows per newton (m/N); `None`: chosen at the first step with
    /// contacts so the largest normal force draws 0.3 m.
    pub force_scale: Option<f32>,
    /// Radius of contact points (m).
    pub contact_radius: f32,
    /// Send stickslip's viewer layout ([`layout::blueprint`]) with the first logged step, so
    /// that the recording opens with the 3D scene, contacts by regime and the friction time
    /// series side by side.
    pub blueprint: bool,
}

impl Default for LogOptions {
    fn default() -> Self {
        LogOptions {
            every: 1,
            max_contact_series: 16,
            max_body_series: 32,
            force_scale: None,
            contact_radius: 0.01,
            blueprint: true,
        }
    }
}

/// Class id of a regime in the `world/contacts` annotation context: its code.
pub fn regime_class(r: Regime) -> u16 {
    r.code() as u16
}

/// A regime's colour: `Regime::srgb`, as in the bevy add-ons' gizmos.
fn regime_color(r: Regime) -> Color {
    let [red, green, blue] = r.srgb();
    Color::from_rgb(red, green, blue)
}

const PALETTE: [[u8; 3]; 6] = [
    [31, 119, 180],
    [148, 103, 189],
    [140, 86, 75],
    [227, 119, 194],
    [188, 189, 34],
    [23, 190, 207],
];

/// Keeps only characters rerun accepts unescaped in an entity path part.
fn sanitize(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if s.is_empty() { "_".to_string() } else { s }
}

/// Logs a rapier world and its stickslip modifier to a rerun recording.
pub struct RerunLogger {
    rec: RecordingStream,
    opts: LogOptions,
    names: HashMap<RigidBodyHandle, String>,
    start: HashMap<RigidBodyHandle, Vector>,
    shapes_logged: HashSet<ColliderHandle>,
    styled: HashSet<String>,
    contact_names: HashMap<(ColliderHandle, ColliderHandle, usize), String>,
    body_series: HashSet<RigidBodyHandle>,
    force_scale: Option<f32>,
    /// m per N·m of the rolling-resistance torque arrows (set from the first torques seen).
    torque_scale: Option<f32>,
    logged: u64,
    static_done: bool,
}

/// Per-body sums over a step's contacts.
#[derive(Default, Clone, Copy)]
struct BodyLoad {
    normal: f64,
    friction: [f64; 3],
    power: f64,
}

impl RerunLogger {
    /// A logger writing to `rec`.
    pub fn new(rec: RecordingStream, opts: LogOptions) -> Self {
        RerunLogger {
            rec,
            force_scale: opts.force_scale,
            torque_scale: None,
            opts: LogOptions {
                every: opts.every.max(1),
                ..opts
            },
            names: HashMap::new(),
            start: HashMap::new(),
            shapes_logged: HashSet::new(),
            styled: HashSet::new(),
            contact_names: HashMap::new(),
            body_series: HashSet::new(),
            logged: 0,
            static_done: false,
        }
    }

    /// The recording stream.
    pub fn recording(&self) -> &RecordingStream {
        &self.rec
    }

    /// The options.
    pub fn options(&self) -> &LogOptions {
        &self.opts
    }

    /// Names a body in entity paths (characters other than letters, digits, `_`, `-` become
    /// `_`). Unnamed bodies are `body_{index}`.
    pub fn set_body_name(&mut self, body: RigidBodyHandle, name: impl AsRef<str>) {
        self.names.insert(body, sanitize(name.as_ref()));
    }

    /// The entity-path name of a body.
    pub fn body_name(&self, body: RigidBodyHandle) -> String {
        self.names
            .get(&body)
            .cloned()
            .unwrap_or_else(|| format!("body_{}", body.0.into_raw_parts().0))
    }

    /// Steps logged so far.
    pub fn logged_steps(&self) -> u64 {
        self.logged
    }

    /// Whether [`Self::log_step`] logs `step`.
    pub fn wants(&self, step: u64) -> bool {
        step.is_multiple_of(self.opts.every)
    }

    /// Logs the state after `step` steps (the time is the modifier's simulated time) if `step`
    /// is a multiple of [`LogOptions::every`]; returns whether it logged. Contacts and world
    /// totals are logged from what the modifier reads back: turn that on with
    /// [`StickSlip::set_read_back`] (`ReadBack::Contacts`; `ReadBack::Totals` for the totals
    /// alone, which stay zero with the default `ReadBack::Off`).
    pub fn log_step<H: PhysicsHooks>(
        &mut self,
        step: u64,
        world: &PhysicsWorld,
        stickslip: &StickSlip<H>,
    ) -> Result<bool, LogError> {
        if !self.wants(step) {
            return Ok(false);
        }
        self.log_step_always(step, world, stickslip)?;
        Ok(true)
    }

    /// Logs the state after `step` steps regardless of [`LogOptions::every`] (e.g. the last
    /// step of a run).
    pub fn log_step_always<H: PhysicsHooks>(
        &mut self,
        step: u64,
        world: &PhysicsWorld,
        stickslip: &StickSlip<H>,
    ) -> Result<(), LogError> {
        let rec = &self.rec;
        rec.set_time_sequence(paths::STEP, step as i64);
        rec.set_duration_secs(paths::SIM_TIME, stickslip.time());
        if !self.static_done {
            if self.opts.blueprint {
                layout::blueprint().send(rec, rerun::blueprint::BlueprintActivation::default())?;
            }
            self.log_statics()?;
            self.static_done = true;
        }
        self.log_bodies(world)?;
        self.log_contacts(world, stickslip)?;
        self.log_rolling(world, stickslip)?;
        self.log_vibrations(world, stickslip)?;
        self.logged += 1;
        Ok(())
    }

    /// Flushes the sink, reporting failures (e.g. an unwritable file).
    pub fn flush(&self) -> Result<(), LogError> {
        self.rec
            .flush_blocking()
            .map_err(|e| LogError::Flush(e.to_string()))
    }

    fn log_statics(&mut self) -> Result<(), LogError> {
        let rec = &self.rec;
        rec.log_static(paths::WORLD, &ViewCoordinates::RIGHT_HAND_Y_UP())?;
        rec.log_static(
            paths::CONTACTS,
            &AnnotationContext::new([
                (
                    regime_class(Regime::Sticking),
                    "sticking",
                    regime_color(Regime::Sticking).0,
                ),
                (
                    regime_class(Regime::StickSlip),
                    "stick-slip",
                    regime_color(Regime::StickSlip).0,
                ),
                (
                    regime_class(Regime::Sliding),
                    "sliding",
                    regime_color(Regime::Sliding).0,
                ),
            ]),
        )?;
        for (series, regime) in
            paths::REGIME_SERIES
                .iter()
                .zip([Regime::Sticking, Regime::StickSlip, Regime::Sliding])
        {
            self.style(
                &paths::world_series(series),
                &format!("{series} contacts"),
                regime_color(regime),
            )?;
        }
        for (k, series) in paths::TOTAL_SERIES.iter().enumerate() {
            self.style(&paths::world_series(series), series, palette(k))?;
        }
        Ok(())
    }

    fn style(&mut self, path: &str, name: &str, color: Color) -> Result<(), LogError> {
        if self.styled.insert(path.to_string()) {
            self.rec.log_static(
                path,
                &SeriesLines::new().with_names([name]).with_colors([color]),
            )?;
        }
        Ok(())
    }

    fn scalar(&self, path: &str, value: f64) -> Result<(), LogError> {
        if value.is_finite() {
            self.rec.log(path, &Scalars::single(value))?;
        }
        Ok(())
    }

    fn log_bodies(&mut self, world: &PhysicsWorld) -> Result<(), LogError> {
        for (index, (handle, body)) in world.bodies.iter().enumerate() {
            let name = self.body_name(handle);
            let p = body.translation();
            let q = body.rotation();
            self.rec.log(
                paths::body(&name),
                &Transform3D::from_translation(p.to_array())
                    .with_quaternion(Quaternion::from_xyzw([q.x, q.y, q.z, q.w])),
            )?;
            for (j, &ch) in body.colliders().iter().enumerate() {
                if self.shapes_logged.insert(ch)
                    && let Some(collider) = world.colliders.get(ch)
                {
                    log_shape(&self.rec, &paths::collider(&name, j), collider, body, index)?;
                }
            }
            if !body.is_fixed() {
                self.start.entry(handle).or_insert(p);
            }
        }
        Ok(())
    }

    fn log_contacts<H: PhysicsHooks>(
        &mut self,
        world: &PhysicsWorld,
        stickslip: &StickSlip<H>,
    ) -> Result<(), LogError> {
        // Nothing to draw unless the modifier reads contacts back (ReadBack::Contacts).
        let reports = stickslip.reports().unwrap_or_default();
        if self.force_scale.is_none() && !reports.is_empty() {
            let max = reports.iter().map(|r| r.normal_force).fold(0.0, f64::max);
            if max > 0.0 {
                self.force_scale = Some((0.3 / max) as f32);
            }
        }
        let scale = self.force_scale.unwrap_or(0.0);
        let points: Vec<[f32; 3]> = reports.iter().map(|r| r.point).collect();
        let colors: Vec<Color> = reports.iter().map(|r| regime_color(r.regime)).collect();
        let classes: Vec<u16> = reports.iter().map(|r| regime_class(r.regime)).collect();
        self.rec.log(
            paths::CONTACT_POINTS,
            &Points3D::new(points.iter().copied())
                .with_colors(colors.iter().copied())
                .with_class_ids(classes)
                .with_radii([self.opts.contact_radius]),
        )?;
        self.rec.log(
            paths::FRICTION_ARROWS,
            &Arrows3D::from_vectors(reports.iter().map(|r| r.friction_force.map(|f| f * scale)))
                .with_origins(points)
                .with_colors(colors),
        )?;

        // World totals.
        let totals = stickslip.totals().unwrap_or_default();
        for (series, count) in
            paths::REGIME_SERIES
                .iter()
                .zip([totals.sticking, totals.stick_slip, totals.sliding])
        {
            self.scalar(&paths::world_series(series), count as f64)?;
        }
        for (series, value) in paths::TOTAL_SERIES.iter().zip([
            totals.normal_force,
            totals.friction_force,
            totals.dissipated_power,
            totals.dissipated_energy,
        ]) {
            self.scalar(&paths::world_series(series), value)?;
        }

        // Per body.
        let mut loads: HashMap<RigidBodyHandle, BodyLoad> = HashMap::new();
        for r in reports {
            for (c, sign) in [(r.collider1, -1.0), (r.collider2, 1.0)] {
                let Some(body) = world.colliders.get(c).and_then(|c| c.parent()) else {
                    continue;
                };
                let load = loads.entry(body).or_default();
                load.normal += r.normal_force;
                for k in 0..3 {
                    load.friction[k] += sign * r.friction_force[k] as f64;
                }
                load.power += r.dissipated_power;
            }
        }
        for (handle, body) in world.bodies.iter() {
            if body.is_fixed() {
                continue;
            }
            if !self.body_series.contains(&handle) {
                if self.body_series.len() >= self.opts.max_body_series {
                    continue;
                }
                self.body_series.insert(handle);
            }
            let name = self.body_name(handle);
            let load = loads.get(&handle).copied().unwrap_or_default();
            let friction = norm3(load.friction);
            let start = self
                .start
                .get(&handle)
                .copied()
                .unwrap_or(body.translation());
            let values = [
                body.linvel().length() as f64,
                (body.translation() - start).length() as f64,
                load.normal,
                friction,
                if load.normal > 0.0 {
                    friction / load.normal
                } else {
                    0.0
                },
                load.power,
            ];
            for (k, (series, value)) in paths::BODY_SERIES.iter().zip(values).enumerate() {
                let path = paths::body_series(&name, series);
                self.style(&path, &format!("{name} {series}"), palette(k))?;
                self.scalar(&path, value)?;
            }
        }

        // Per contact.
        let mut seen: HashMap<(ColliderHandle, ColliderHandle), usize> = HashMap::new();
        for r in reports {
            let k = seen.entry((r.collider1, r.collider2)).or_insert(0);
            let key = (r.collider1, r.collider2, *k);
            *k += 1;
            let Some(name) = self.contact_name(world, key) else {
                continue;
            };
            self.log_contact_series(&name, r)?;
        }
        Ok(())
    }

    /// The series name of a pair's `k`-th manifold, `None` once `max_contact_series` names
    /// are taken.
    fn contact_name(
        &mut self,
        world: &PhysicsWorld,
        key: (ColliderHandle, ColliderHandle, usize),
    ) -> Option<String> {
        if let Some(n) = self.contact_names.get(&key) {
            return Some(n.clone());
        }
        if self.contact_names.len() >= self.opts.max_contact_series {
            return None;
        }
        let mut n = format!(
            "{}--{}",
            self.collider_name(world, key.0),
            self.collider_name(world, key.1)
        );
        if key.2 > 0 {
            n.push_str(&format!("_{}", key.2));
        }
        self.contact_names.insert(key, n.clone());
        Some(n)
    }

    /// The pairs resisting rolling or spinning (`StickSlip::rolling_reports`): torque arrows
    /// and per-pair series. Nothing is logged for a world without such pairs.
    fn log_rolling<H: PhysicsHooks>(
        &mut self,
        world: &PhysicsWorld,
        stickslip: &StickSlip<H>,
    ) -> Result<(), LogError> {
        let reports = stickslip.rolling_reports(&world.impulse_joints);
        if reports.is_empty() && self.torque_scale.is_none() {
            return Ok(());
        }
        let torque = |r: &RollingReport| {
            let t = r.rolling_torque;
            let s = r.spinning_torque;
            [t[0] + s[0], t[1] + s[1], t[2] + s[2]]
        };
        // 0.3 m for the largest torque cap first seen (μ · arm · F_n: known from a contact's
        // first step, where the torque itself may be near zero; until one is, no length).
        if self.torque_scale.is_none_or(|s| s == 0.0) {
            let max = reports
                .iter()
                .map(|r| {
                    let rolling = r.rolling_limit * r.rolling_arm as f64;
                    let spinning = r.spinning_limit * r.spinning_arm as f64;
                    rolling.max(spinning) * r.normal_force
                })
                .fold(0.0, f64::max);
            self.torque_scale = Some(if max > 0.0 { (0.3 / max) as f32 } else { 0.0 });
        }
        let scale = self.torque_scale.unwrap_or(0.0);
        let regime = |r: &RollingReport| r.rolling.or(r.spinning).unwrap_or(Regime::Sticking);
        self.rec.log(
            paths::ROLLING_ARROWS,
            &Arrows3D::from_vectors(reports.iter().map(|r| torque(r).map(|t| t * scale)))
                .with_origins(reports.iter().map(|r| r.point))
                .with_colors(reports.iter().map(|r| regime_color(regime(r))))
                .with_class_ids(reports.iter().map(|r| regime_class(regime(r)))),
        )?;
        for r in &reports {
            let Some(name) = self.contact_name(world, (r.collider1, r.collider2, 0)) else {
                continue;
            };
            let values = [
                norm3(r.rolling_torque.map(f64::from)),
                norm3(r.spinning_torque.map(f64::from)),
                r.effective_rolling_mu(),
                r.effective_spinning_mu(),
            ];
            for (k, (series, value)) in paths::ROLLING_SERIES.iter().zip(values).enumerate() {
                let path = paths::contact_series(&name, series);
                self.style(&path, &format!("{name} {series}"), palette(k + 2))?;
                self.scalar(&path, value)?;
            }
        }
        Ok(())
    }

    fn log_contact_series(&mut self, pair: &str, r: &ContactReport) -> Result<(), LogError> {
        let v = r.slip_velocity;
        let slip = ((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) as f64).sqrt();
        let values = [
            r.mu,
            slip,
            r.normal_force,
            r.effective_mu(),
            r.dissipated_power,
        ];
        for (k, (series, value)) in paths::CONTACT_SERIES.iter().zip(values).enumerate() {
            let path = paths::contact_series(pair, series);
            self.style(&path, &format!("{pair} {series}"), palette(k))?;
            self.scalar(&path, value)?;
        }
        Ok(())
    }

    fn collider_name(&self, world: &PhysicsWorld, c: ColliderHandle) -> String {
        let Some(collider) = world.colliders.get(c) else {
            return format!("collider_{}", c.0.into_raw_parts().0);
        };
        match collider.parent() {
            Some(b) => {
                let name = self.body_name(b);
                let siblings = world.bodies.get(b).map_or(&[][..], |b| b.colliders());
                match siblings.iter().position(|&s| s == c) {
                    Some(j) if siblings.len() > 1 => format!("{name}.{j}"),
                    _ => name,
                }
            }
            None => format!("collider_{}", c.0.into_raw_parts().0),
        }
    }

    fn log_vibrations<H: PhysicsHooks>(
        &mut self,
        world: &PhysicsWorld,
        stickslip: &StickSlip<H>,
    ) -> Result<(), LogError> {
        let t = stickslip.time();
        for (handle, _) in world.colliders.iter() {
            if let Some(source) = stickslip.vibration(handle) {
                let name = self.collider_name(world, handle);
                let path = paths::vibration_series(&name);
                self.style(
                    &path,
                    &format!("{name} vibration w(f t + φ)"),
                    Color::from_rgb(23, 190, 207),
                )?;
                self.scalar(&path, source.signal(t))?;
            }
        }
        Ok(())
    }
}

fn palette(k: usize) -> Color {
    let c = PALETTE[k % PALETTE.len()];
    Color::from_rgb(c[0], c[1], c[2])
}

fn norm3(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Logs a collider's pose relative to its body and its shape, statically.
fn log_shape(
    rec: &RecordingStream,
    path: &str,
    collider: &Collider,
    body: &RigidBody,
    body_index: usize,
) -> Result<(), LogError> {
    let local = collider
        .position_wrt_parent()
        .copied()
        .unwrap_or(Pose::IDENTITY);
    let (t, q) = (local.translation, local.rotation);
    rec.log_static(
        path,
        &Transform3D::from_translation(t.to_array())
            .with_quaternion(Quaternion::from_xyzw([q.x, q.y, q.z, q.w])),
    )?;
    let color = if body.is_fixed() {
        Color::from_rgb(150, 150, 150)
    } else if body.is_kinematic() {
        Color::from_rgb(90, 140, 200)
    } else {
        palette(body_index)
    };
    let shape = collider.shape();
    if let Some(c) = shape.as_cuboid() {
        rec.log_static(
            path,
            &Boxes3D::from_half_sizes([c.half_extents.to_array()])
                .with_colors([color])
                .with_fill_mode(FillMode::Solid),
        )?;
    } else if let Some(b) = shape.as_ball() {
        rec.log_static(
            path,
            &Ellipsoids3D::from_radii([b.radius])
                .with_colors([color])
                .with_fill_mode(FillMode::Solid),
        )?;
    } else if let Some(c) = shape.as_capsule() {
        // rerun capsules start at their translation and extend along +z.
        let (a, b) = (c.segment.a, c.segment.b);
        let d = b - a;
        let rot = Rotation::from_rotation_arc(Vector::Z, d.normalize_or(Vector::Z));
        rec.log_static(
            path,
            &Capsules3D::from_lengths_and_radii([d.length()], [c.radius])
                .with_translations([a.to_array()])
                .with_quaternions([Quaternion::from_xyzw([rot.x, rot.y, rot.z, rot.w])])
                .with_colors([color])
                .with_fill_mode(FillMode::Solid),
        )?;
    } else if let Some(m) = shape.as_trimesh() {
        rec.log_static(
            path,
            &Mesh3D::new(m.vertices().iter().map(|v| v.to_array()))
                .with_triangle_indices(m.indices().iter().copied())
                .with_albedo_factor(color.0),
        )?;
    }
    Ok(())
}
