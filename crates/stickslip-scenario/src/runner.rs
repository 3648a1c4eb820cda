//! [`Runner`]: steps a [`Scene`] (drivers, then the stickslip step) and keeps a [`Summary`].

use crate::build::Scene;
use crate::drive::apply_drivers;
use crate::spec::BodyKind;
use rapier3d::prelude::*;
use serde::{Deserialize, Serialize};
use stickslip_core::law::Regime;
use stickslip_rapier::StickSlip;
use stickslip_rapier::snapshot::{SnapshotError, StickSlipSnapshot, load_value, save_value};

/// Steps a scene and collects statistics.
pub struct Runner {
    scene: Scene,
    steps: u64,
    regime_steps: RegimeCounts,
    max_contacts: usize,
}

/// Contacts per regime.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct RegimeCounts {
    /// Sticking.
    pub sticking: u64,
    /// Stick-slip transition.
    pub stick_slip: u64,
    /// Sliding.
    pub sliding: u64,
}

impl RegimeCounts {
    /// Sum of the three.
    pub fn total(&self) -> u64 {
        self.sticking + self.stick_slip + self.sliding
    }

    fn add(&mut self, r: Regime) {
        match r {
            Regime::Sticking => self.sticking += 1,
            Regime::StickSlip => self.stick_slip += 1,
            Regime::Sliding => self.sliding += 1,
        }
    }
}

/// One body at the end of a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodySummary {
    /// Name.
    pub name: String,
    /// `fixed`, `dynamic` or `kinematic`.
    pub kind: BodyKind,
    /// Position minus start position (m).
    pub displacement: [f64; 3],
    /// |displacement| (m).
    pub distance: f64,
    /// Linear velocity (m/s).
    pub velocity: [f64; 3],
    /// |velocity| (m/s).
    pub speed: f64,
}

/// What a run did.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Scenario name.
    pub scenario: String,
    /// Steps taken.
    pub steps: u64,
    /// Simulated time (s).
    pub sim_time: f64,
    /// Time step (s).
    pub dt: f64,
    /// Stickslip contacts per regime after the last step.
    pub contacts: RegimeCounts,
    /// Contact-steps per regime summed over the run.
    pub regime_steps: RegimeCounts,
    /// Most stickslip contacts seen in one step.
    pub max_contacts: usize,
    /// Energy dissipated by stickslip friction (J).
    pub dissipated_energy: f64,
    /// Whether every body pose and velocity is finite.
    pub finite: bool,
    /// Non-fixed bodies.
    pub bodies: Vec<BodySummary>,
}

impl Runner {
    /// A runner at step 0 of `scene`.
    pub fn new(scene: Scene) -> Self {
        Runner {
            scene,
            steps: 0,
            regime_steps: RegimeCounts::default(),
            max_contacts: 0,
        }
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The scene, mutably (e.g. to change a vibration source between steps).
    pub fn scene_mut(&mut self) -> &mut Scene {
        &mut self.scene
    }

    /// Takes the scene back.
    pub fn into_scene(self) -> Scene {
        self.scene
    }

    /// Steps taken.
    pub fn steps_done(&self) -> u64 {
        self.steps
    }

    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        self.scene.stickslip.time()
    }

    /// Applies the drivers at the current time, then steps the world with the modifier.
    pub fn step(&mut self) {
        let scene = &mut self.scene;
        let t = scene.stickslip.time();
        let dt = scene.world.integration_parameters.dt as f64;
        let handles = |i: usize| scene.bodies[i].handle;
        apply_drivers(&scene.drivers, &mut scene.world.bodies, handles, t, dt);
        scene.stickslip.step(&mut scene.world);
        self.steps += 1;
        let reports = scene.stickslip.reports().unwrap_or_default();
        self.max_contacts = self.max_contacts.max(reports.len());
        for r in reports {
            self.regime_steps.add(r.regime);
        }
    }

    /// Takes `steps` steps, calling `after` after each one.
    pub fn run_with(&mut self, steps: u64, mut after: impl FnMut(&Runner)) {
        for _ in 0..steps {
            self.step();
            after(self);
        }
    }

    /// Takes `steps` steps.
    pub fn run(&mut self, steps: u64) {
        self.run_with(steps, |_| {});
    }

    /// The statistics so far.
    pub fn summary(&self) -> Summary {
        let scene = &self.scene;
        let mut contacts = RegimeCounts::default();
        for r in scene.stickslip.reports().unwrap_or_default() {
            contacts.add(r.regime);
        }
        let mut finite = true;
        let bodies = scene
            .bodies
            .iter()
            .filter_map(|b| {
                let body = scene.world.bodies.get(b.handle)?;
                let p = body.translation();
                let v = body.linvel();
                finite &= p.is_finite() && v.is_finite() && body.rotation().is_finite();
                (b.kind != BodyKind::Fixed).then(|| {
                    let d = [
                        p.x as f64 - b.start[0],
                        p.y as f64 - b.start[1],
                        p.z as f64 - b.start[2],
                    ];
                    let v = [v.x as f64, v.y as f64, v.z as f64];
                    BodySummary {
                        name: b.name.clone(),
                        kind: b.kind,
                        displacement: d,
                        distance: norm(d),
                        velocity: v,
                        speed: norm(v),
                    }
                })
            })
            .collect();
        Summary {
            scenario: scene.name.clone(),
            steps: self.steps,
            sim_time: self.time(),
            dt: scene.world.integration_parameters.dt as f64,
            contacts,
            regime_steps: self.regime_steps,
            max_contacts: self.max_contacts,
            dissipated_energy: scene
                .stickslip
                .totals()
                .unwrap_or_default()
                .dissipated_energy,
            finite,
            bodies,
        }
    }
}

/// Header kind of a runner snapshot file (see [`stickslip_rapier::snapshot`]).
const KIND_RUNNER: u8 = 2;

/// A runner snapshot being written: the world by reference.
#[derive(Serialize)]
struct RunnerSnapshotRef<'a> {
    scenario: &'a str,
    steps: u64,
    regime_steps: RegimeCounts,
    max_contacts: u64,
    world: &'a PhysicsWorld,
    friction: StickSlipSnapshot,
}

/// A runner snapshot read back.
#[derive(Deserialize)]
struct RunnerSnapshot {
    scenario: String,
    steps: u64,
    regime_steps: RegimeCounts,
    max_contacts: u64,
    world: PhysicsWorld,
    friction: StickSlipSnapshot,
}

impl Runner {
    /// Writes the run's state — rapier's world, the stickslip modifier's state and this
    /// runner's counters — to `writer`, in stickslip's snapshot format (header kind 2, see
    /// [`stickslip_rapier::snapshot`]). [`Runner::resume`] continues from it bit-identically.
    pub fn save_snapshot<W: std::io::Write>(&self, writer: W) -> Result<(), SnapshotError> {
        let bundle = RunnerSnapshotRef {
            scenario: &self.scene.name,
            steps: self.steps,
            regime_steps: self.regime_steps,
            max_contacts: self.max_contacts as u64,
            world: &self.scene.world,
            friction: self.scene.stickslip.snapshot(),
        };
        save_value(writer, KIND_RUNNER, &bundle)
    }

    /// A runner continuing the run saved by [`Runner::save_snapshot`]: `scene` is built from
    /// the same scenario (it supplies names, start positions and drivers); its world and
    /// modifier are replaced by the saved ones, and the step count and statistics go on from
    /// the saved values. The snapshot must name the same scenario and hold every body and
    /// collider of `scene`; everything in it is validated (a typed error, never a panic).
    pub fn resume<R: std::io::Read>(mut scene: Scene, reader: R) -> Result<Self, SnapshotError> {
        let snap: RunnerSnapshot = load_value(reader, KIND_RUNNER)?;
        let mismatch = |reason: String| SnapshotError::Invalid {
            field: "scenario",
            reason,
        };
        if snap.scenario != scene.name {
            return Err(mismatch(format!(
                "the snapshot is of scenario {:?}, not {:?}",
                snap.scenario, scene.name
            )));
        }
        if let Some(b) = scene
            .bodies
            .iter()
            .find(|b| !snap.world.bodies.contains(b.handle))
        {
            return Err(mismatch(format!(
                "body {:?} is not in the snapshot",
                b.name
            )));
        }
        if let Some(c) = scene
            .colliders
            .iter()
            .find(|c| !snap.world.colliders.contains(c.handle))
        {
            return Err(mismatch(format!(
                "collider {} of body {:?} is not in the snapshot",
                c.index, scene.bodies[c.body].name
            )));
        }
        let stickslip = StickSlip::restore(&snap.friction, &snap.world.colliders, ())?;
        // Counters far beyond any run (2⁵³ steps), so that counting on never overflows.
        const MAX_COUNT: u64 = 1 << 53;
        let r = snap.regime_steps;
        let counts = [
            snap.steps,
            snap.max_contacts,
            r.sticking,
            r.stick_slip,
            r.sliding,
        ];
        if counts.iter().any(|&n| n > MAX_COUNT) {
            return Err(SnapshotError::Invalid {
                field: "runner counters",
                reason: "a step or contact count beyond 2^53".into(),
            });
        }
        let max_contacts = snap.max_contacts as usize;
        scene.world = snap.world;
        scene.stickslip = stickslip;
        Ok(Runner {
            scene,
            steps: snap.steps,
            regime_steps: snap.regime_steps,
            max_contacts,
        })
    }
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}
