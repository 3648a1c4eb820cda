//! Benchmark scenes of `benches/step_cost.rs`: the same
//! rapier world stepped with plain rapier friction, a no-op contact hook, or stickslip with
//! each law, with and without a vibration source.
//!
//! Scenes (every dynamic body has sleeping disabled, so every contact stays active):
//! - `plane_<n>`: n boxes (0.5 m, 125 kg) resting in a square grid on a fixed ground,
//!   4 contact points per box, dt = 1/60 s;
//! - `pile`: 4-high stacks of the same boxes (box–ground and box–box contacts), dt = 1/60 s;
//! - `chain`: a row of 250 boxes (0.1 m, 1 kg) on the ground coupled by spring joints, driven at
//!   one end by a kinematic body oscillating at 50 Hz (2 cm), dt = 1/1000 s;
//! - `trough`: a kinematic vibratory trough (25 Hz, 1.5 mm along a 25° throw direction,
//!   machine number ≈ 1.6, parts hop) carrying 480 small parts, dt = 1/500 s;
//! - `towers_<n>`: plank towers, the stacking demo of every engine: a 3 × 3 grid of towers of
//!   12 crossed layers of four 1.6 m planks (the tower of `stickslip_fixtures::ordinary::stack`, tall
//!   enough to stand still in plain rapier), n planks, dt = 1/60 s;
//! - `rolling_<n>`: n balls (r 0.1 m) rolling without slipping across a fixed ground at 1 m/s,
//!   dt = 1/60 s.
//!
//! Scenes after rapier's own `examples3d` (shapes and sizes of the kind the examples use,
//! friction 0.5, sleeping left on as the examples leave it except where the scene would
//! sleep before it is measured, stickslip on every collider):
//! - `drum_<n>`: n cubes (0.2 m) tumbling in a closed drum (r 3 m) turning at 1 rad/s on a
//!   velocity-based kinematic body (the washer example);
//! - `heightfield_<n>`: n boxes, balls and capsules dropped on a wavy heightfield;
//! - `compounds_<n>`: n U-shaped compound bodies (three cuboids) dropped in a heap;
//! - `platforms_<n>`: n boxes in 4-high stacks on six position-based kinematic platforms
//!   swinging 1 m at 0.2 Hz (peak acceleration 1.6 m/s², below μg: the stacks ride along);
//! - `dominoes_<n>`: n dominoes in rows of 100, the first of each row pushed;
//! - `keva_444`: a tower in the layout of rapier's `keva3` (three blocks, 444 planks of
//!   0.1 × 0.5 × 2 m, crossed layers, faces touching at zero gap), sleeping off so it stays
//!   active, measured after 6 s of settling.
//!
//! All at dt = 1/60 s.
#![allow(dead_code)]

use rapier3d::prelude::*;
use stickslip::core::law::{Law, Physical, Regularization, Regularized};
use stickslip::core::sliding_curve::Curve;
use stickslip::core::waveform::Waveform;
use stickslip::rapier::{
    Amplitude, FrictionMaterial, StickSlip, VibrationDirection, VibrationMode, VibrationSource,
};

/// Coefficient of plain rapier colliders, and the laws' break-away coefficient.
pub const MU: f32 = 0.5;
/// The laws' μ_max = μ_ve (flat sliding curve).
pub const MU_MAX: f64 = 0.55;
/// EP stiffness c (1/m).
pub const C: f64 = 1e4;
/// Regul's ġ_t0 (m/s).
pub const V_REG: f64 = 0.01;

/// A scene to step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scene {
    /// `boxes` boxes on a plane.
    Plane { boxes: usize },
    /// `stacks` stacks of `height` boxes.
    Pile { stacks: usize, height: usize },
    /// A row of `links` boxes coupled by springs, driven at one end.
    Chain { links: usize },
    /// A vibrating trough with `parts` parts.
    Trough { parts: usize },
    /// A grid of `grid` × `grid` plank towers of `layers` crossed layers of four planks.
    Towers { grid: usize, layers: usize },
    /// `balls` balls rolling across the ground.
    Rolling { balls: usize },
    /// `cubes` cubes tumbling in a turning drum.
    Drum { cubes: usize },
    /// `bodies` mixed bodies dropped on a heightfield.
    Heightfield { bodies: usize },
    /// `bodies` U-shaped compounds dropped in a heap.
    Compounds { bodies: usize },
    /// `boxes` boxes in stacks on swinging kinematic platforms.
    Platforms { boxes: usize },
    /// `count` dominoes in rows of 100, the first of each row pushed.
    Dominoes { count: usize },
    /// The 444-plank tower of `stickslip_fixtures::ordinary::stack(Stack::Keva, 3, ..)` (rapier's `keva3`
    /// layout, three blocks).
    Keva,
}

impl Scene {
    /// Boxes for about `points` contact points on a plane (4 per box).
    pub fn plane_for_points(points: usize) -> Scene {
        Scene::Plane {
            boxes: points.div_ceil(4),
        }
    }

    /// Stable name used as the criterion group.
    pub fn name(&self) -> String {
        match *self {
            Scene::Plane { boxes } => format!("plane_{}", boxes * 4),
            Scene::Pile { stacks, height } => format!("pile_{}", stacks * height * 4),
            Scene::Chain { links } => format!("chain_{links}"),
            Scene::Trough { parts } => format!("trough_{parts}"),
            Scene::Towers { grid, layers } => format!("towers_{}", grid * grid * layers * 4),
            Scene::Rolling { balls } => format!("rolling_{balls}"),
            Scene::Drum { cubes } => format!("drum_{cubes}"),
            Scene::Heightfield { bodies } => format!("heightfield_{bodies}"),
            Scene::Compounds { bodies } => format!("compounds_{bodies}"),
            Scene::Platforms { boxes } => format!("platforms_{boxes}"),
            Scene::Dominoes { count } => format!("dominoes_{count}"),
            Scene::Keva => "keva_444".to_string(),
        }
    }

    /// One line saying what the scene is.
    pub fn describe(&self) -> String {
        match *self {
            Scene::Plane { boxes } => format!("{boxes} boxes resting on a plane, dt 1/60 s"),
            Scene::Pile { stacks, height } => {
                format!("{stacks} stacks of {height} boxes on a plane, dt 1/60 s")
            }
            Scene::Chain { links } => format!(
                "row of {links} boxes coupled by springs, one end driven at 50 Hz, dt 1/1000 s"
            ),
            Scene::Trough { parts } => {
                format!("vibratory trough (25 Hz, 1.5 mm) carrying {parts} parts, dt 1/500 s")
            }
            Scene::Towers { grid, layers } => format!(
                "{grid} x {grid} plank towers of {layers} crossed layers of 4 planks, dt 1/60 s"
            ),
            Scene::Rolling { balls } => {
                format!("{balls} balls rolling across a plane at 1 m/s, dt 1/60 s")
            }
            Scene::Drum { cubes } => {
                format!("{cubes} cubes tumbling in a drum turning at 1 rad/s, dt 1/60 s")
            }
            Scene::Heightfield { bodies } => {
                format!("{bodies} boxes, balls and capsules dropped on a heightfield, dt 1/60 s")
            }
            Scene::Compounds { bodies } => {
                format!("{bodies} U-shaped compounds dropped in a heap, dt 1/60 s")
            }
            Scene::Platforms { boxes } => format!(
                "{boxes} boxes in 4-high stacks on six platforms swinging 1 m at 0.2 Hz, dt 1/60 s"
            ),
            Scene::Dominoes { count } => {
                format!("{count} dominoes in rows of 100 toppling, dt 1/60 s")
            }
            Scene::Keva => {
                "a 444-plank tower in rapier's keva3 layout, at rest, dt 1/60 s".to_string()
            }
        }
    }

    /// Time step (s).
    pub fn dt(&self) -> f32 {
        match self {
            Scene::Plane { .. }
            | Scene::Pile { .. }
            | Scene::Towers { .. }
            | Scene::Rolling { .. } => 1.0 / 60.0,
            Scene::Chain { .. } => 1.0 / 1000.0,
            Scene::Trough { .. } => 1.0 / 500.0,
            _ => 1.0 / 60.0,
        }
    }

    /// Frequency of the time-resolved vibration source (resolved by ≥ 10 steps a period).
    pub fn resolved_frequency(&self) -> f64 {
        match self {
            Scene::Plane { .. }
            | Scene::Pile { .. }
            | Scene::Towers { .. }
            | Scene::Rolling { .. } => 5.0,
            Scene::Chain { .. } => 100.0,
            Scene::Trough { .. } => 50.0,
            _ => 5.0,
        }
    }

    /// Steps to settle before measuring.
    pub fn settle_steps(&self) -> usize {
        match self {
            Scene::Plane { .. }
            | Scene::Pile { .. }
            | Scene::Towers { .. }
            | Scene::Rolling { .. } => 60,
            Scene::Chain { .. } => 200,
            Scene::Trough { .. } => 250,
            // Dropped heaps land and start settling; the drum turns a quarter; the first
            // dominoes fall.
            Scene::Drum { .. } | Scene::Heightfield { .. } | Scene::Compounds { .. } => 90,
            Scene::Platforms { .. } | Scene::Dominoes { .. } => 60,
            // The tower rocks, under plain rapier too, until about 4.5 s.
            Scene::Keva => 360,
        }
    }
}

/// How the world is stepped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    /// Plain rapier, `FrictionModel::Simplified` (rapier's 3D default).
    PlainSimplified,
    /// Plain rapier, `FrictionModel::Coulomb` (per contact point).
    PlainCoulomb,
    /// A hook that does nothing, on the same colliders stickslip attaches to (Simplified).
    NoopHook,
    /// stickslip, elasto-plastic law.
    Ep,
    /// stickslip, regularized law.
    Regul,
    /// stickslip, exact switched law.
    Phys,
    /// stickslip EP with a time-resolved normal vibration source on the ground.
    EpVibResolved,
    /// stickslip EP with an averaged (20 kHz) normal vibration source on the ground.
    EpVibAveraged,
    /// stickslip EP with rolling and spinning resistance (μ_r [`MU_ROLL`]) on every collider
    /// (the rolling scene only).
    EpRolling,
}

impl Variant {
    /// The variants of the small scenes, plain rapier first ([`Variant::EpRolling`] is the
    /// rolling scene's only).
    pub const ALL: [Variant; 8] = [
        Variant::PlainSimplified,
        Variant::PlainCoulomb,
        Variant::NoopHook,
        Variant::Ep,
        Variant::Regul,
        Variant::Phys,
        Variant::EpVibResolved,
        Variant::EpVibAveraged,
    ];

    /// Stable name used as the criterion function id.
    pub fn name(&self) -> &'static str {
        match self {
            Variant::PlainSimplified => "plain_simplified",
            Variant::PlainCoulomb => "plain_coulomb",
            Variant::NoopHook => "noop_hook",
            Variant::Ep => "ep",
            Variant::Regul => "regul",
            Variant::Phys => "phys",
            Variant::EpVibResolved => "ep_vib_resolved",
            Variant::EpVibAveraged => "ep_vib_averaged",
            Variant::EpRolling => "ep_rolling",
        }
    }

    /// Whether stickslip steps the world.
    pub fn is_stickslip(&self) -> bool {
        !matches!(
            self,
            Variant::PlainSimplified | Variant::PlainCoulomb | Variant::NoopHook
        )
    }
}

/// The elasto-plastic law of the benchmarks.
pub fn ep_law() -> Law {
    Law::elasto_plastic(C, MU as f64, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap()
}

/// Rolling and spinning resistance of [`Variant::EpRolling`]: small enough that balls rolled
/// at 1 m/s keep rolling through a whole bench run (they slow by (5/7) μ_r g = 0.0035 m/s²).
pub const MU_ROLL: f64 = 0.0005;

/// The material of a stickslip variant.
pub fn material_of(variant: Variant) -> FrictionMaterial {
    let material = FrictionMaterial::new(law_of(variant));
    if variant == Variant::EpRolling {
        let resist =
            Law::elasto_plastic(C, MU_ROLL, MU_ROLL, Curve::constant(MU_ROLL).unwrap()).unwrap();
        material.with_rolling(resist.clone()).with_spinning(resist)
    } else {
        material
    }
}

/// The law of a stickslip variant.
pub fn law_of(variant: Variant) -> Law {
    match variant {
        Variant::Regul => Law::Regularized(
            Regularized::new(
                Curve::constant(MU_MAX).unwrap(),
                V_REG,
                Regularization::Linear,
            )
            .unwrap(),
        ),
        Variant::Phys => {
            Law::Physical(Physical::new(MU as f64, Curve::constant(MU_MAX).unwrap()).unwrap())
        }
        _ => ep_law(),
    }
}

/// A hook that is called for every contact and changes nothing: the cost floor of any
/// contact modifier (rapier never recycles hooked pairs).
pub struct NoopHook;

impl PhysicsHooks for NoopHook {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        std::hint::black_box(ctx.collider1);
    }
}

enum Stepper {
    Plain,
    Noop(NoopHook),
    StickSlip(Box<StickSlip>),
}

mod examples;

/// A kinematic body moved along `direction` by `amplitude · sin(2π f t)` around `origin`.
pub(crate) struct Driver {
    pub body: RigidBodyHandle,
    pub origin: Vector,
    pub direction: Vector,
    pub amplitude: f32,
    pub frequency: f32,
}

/// A scene being stepped by a variant.
pub struct Bench {
    /// The world.
    pub world: PhysicsWorld,
    stepper: Stepper,
    drivers: Vec<Driver>,
    time: f64,
    /// Colliders the hooks are attached to.
    pub hooked: Vec<ColliderHandle>,
}

fn dynamic_box(world: &mut PhysicsWorld, at: Vector, half: f32, density: f32) -> ColliderHandle {
    world
        .insert(
            RigidBodyBuilder::dynamic().translation(at).can_sleep(false),
            ColliderBuilder::cuboid(half, half, half)
                .density(density)
                .friction(MU),
        )
        .1
}

impl Bench {
    /// Builds `scene` for `variant` (not yet settled).
    pub fn new(scene: Scene, variant: Variant) -> Bench {
        let mut world = PhysicsWorld::default();
        let mut hooked = Vec::new();
        let mut drivers = Vec::new();
        let vib_host;
        match scene {
            Scene::Plane { boxes } | Scene::Pile { stacks: boxes, .. } => {
                let height = match scene {
                    Scene::Pile { height, .. } => height,
                    _ => 1,
                };
                let side = (boxes as f64).sqrt().ceil() as usize;
                let (half, gap) = (0.25f32, 0.6f32);
                let extent = side as f32 * gap * 0.5 + 1.0;
                let ground = world.insert_collider(
                    ColliderBuilder::cuboid(extent, 0.1, extent).friction(MU),
                    None,
                );
                hooked.push(ground);
                vib_host = ground;
                for k in 0..boxes {
                    let (i, j) = ((k % side) as f32, (k / side) as f32);
                    for level in 0..height {
                        let at = Vector::new(
                            (i - side as f32 * 0.5) * gap,
                            0.1 + half + level as f32 * 2.0 * half,
                            (j - side as f32 * 0.5) * gap,
                        );
                        let c = dynamic_box(&mut world, at, half, 1000.0);
                        if height > 1 {
                            hooked.push(c);
                        }
                    }
                }
            }
            Scene::Chain { links } => {
                let (half, gap) = (0.05f32, 0.12f32);
                let length = links as f32 * gap;
                let ground = world.insert_collider(
                    ColliderBuilder::cuboid(length * 0.5 + 2.0, 0.1, 1.0)
                        .translation(Vector::new(length * 0.5, 0.0, 0.0))
                        .friction(MU),
                    None,
                );
                hooked.push(ground);
                vib_host = ground;
                let origin = Vector::new(-gap, 0.1 + half, 0.0);
                let drive = world
                    .insert_body(RigidBodyBuilder::kinematic_position_based().translation(origin));
                let mut prev = drive;
                for i in 0..links {
                    let at = Vector::new(i as f32 * gap, 0.1 + half, 0.0);
                    let (body, _) = world.insert(
                        RigidBodyBuilder::dynamic().translation(at).can_sleep(false),
                        ColliderBuilder::cuboid(half, half, half)
                            .density(1000.0)
                            .friction(MU),
                    );
                    let spring = SpringJointBuilder::new(gap, 2e4, 20.0)
                        .spring_model(MotorModel::ForceBased)
                        .contacts_enabled(false);
                    world.insert_impulse_joint(prev, body, spring);
                    prev = body;
                }
                drivers.push(Driver {
                    body: drive,
                    origin,
                    direction: Vector::X,
                    amplitude: 0.02,
                    frequency: 50.0,
                });
            }
            Scene::Trough { parts } => {
                let (len, width, wall) = (1.2f32, 0.25f32, 0.01f32);
                let origin = Vector::new(0.0, 0.0, 0.0);
                let trough = world
                    .insert_body(RigidBodyBuilder::kinematic_position_based().translation(origin));
                let shapes = [
                    ColliderBuilder::cuboid(len, wall, width),
                    ColliderBuilder::cuboid(len, 0.1, wall).translation(Vector::new(
                        0.0,
                        0.1,
                        width + wall,
                    )),
                    ColliderBuilder::cuboid(len, 0.1, wall).translation(Vector::new(
                        0.0,
                        0.1,
                        -width - wall,
                    )),
                    ColliderBuilder::cuboid(wall, 0.1, width).translation(Vector::new(
                        len + wall,
                        0.1,
                        0.0,
                    )),
                    ColliderBuilder::cuboid(wall, 0.1, width).translation(Vector::new(
                        -len - wall,
                        0.1,
                        0.0,
                    )),
                ];
                for shape in shapes {
                    hooked.push(world.insert_collider(shape.friction(MU), Some(trough)));
                }
                let floor = hooked[0];
                vib_host = floor;
                let half = 0.015f32;
                let gap = 0.04f32;
                let across = ((2.0 * width / gap) as usize).max(1);
                for k in 0..parts {
                    let (i, j) = ((k / across) as f32, (k % across) as f32);
                    let at = Vector::new(
                        -len + gap * (i + 0.75),
                        wall + half + 0.002,
                        -width + gap * (j + 0.5),
                    );
                    let c = dynamic_box(&mut world, at, half, 2500.0);
                    hooked.push(c);
                }
                let throw = 25f32.to_radians();
                drivers.push(Driver {
                    body: trough,
                    origin,
                    direction: Vector::new(throw.cos(), throw.sin(), 0.0),
                    amplitude: 1.5e-3,
                    frequency: 25.0,
                });
            }
            Scene::Towers { grid, layers } => {
                let ground = world.insert_collider(
                    ColliderBuilder::cuboid(20.0, 0.1, 20.0)
                        .translation(Vector::new(0.0, -0.1, 0.0))
                        .friction(MU),
                    None,
                );
                hooked.push(ground);
                vib_host = ground;
                // The tower of `stickslip_fixtures::ordinary::stack(Stack::Tower, ..)`, 2.5 m apart.
                let (long, thick, wide) = (0.8f32, 0.05f32, 0.1f32);
                for t in 0..grid * grid {
                    let centre = Vector::new(
                        ((t % grid) as f32 - (grid - 1) as f32 / 2.0) * 2.5,
                        0.0,
                        ((t / grid) as f32 - (grid - 1) as f32 / 2.0) * 2.5,
                    );
                    for layer in 0..layers {
                        let y = thick + layer as f32 * 2.0 * thick;
                        for i in 0..4 {
                            let across = (i as f32 - 1.5) * 0.4;
                            let (at, half) = if layer % 2 == 0 {
                                (Vector::new(0.0, y, across), Vector::new(long, thick, wide))
                            } else {
                                (Vector::new(across, y, 0.0), Vector::new(wide, thick, long))
                            };
                            let (_, c) = world.insert(
                                RigidBodyBuilder::dynamic()
                                    .translation(centre + at)
                                    .can_sleep(false),
                                ColliderBuilder::cuboid(half.x, half.y, half.z)
                                    .density(500.0)
                                    .friction(MU),
                            );
                            hooked.push(c);
                        }
                    }
                }
            }
            Scene::Rolling { balls } => {
                let r = 0.1f32;
                let side = (balls as f64).sqrt().ceil() as usize;
                let gap = 0.5f32;
                // Far enough that criterion's many iterations never roll the balls off the edge.
                let extent = side as f32 * gap + 20_000.0;
                let ground = world.insert_collider(
                    ColliderBuilder::cuboid(extent, 0.1, extent).friction(MU),
                    None,
                );
                hooked.push(ground);
                vib_host = ground;
                for k in 0..balls {
                    let (i, j) = ((k % side) as f32, (k / side) as f32);
                    let at = Vector::new(
                        (i - side as f32 * 0.5) * gap,
                        0.1 + r,
                        (j - side as f32 * 0.5) * gap,
                    );
                    // Rolling without slipping along +x: v = ω × r.
                    let (_, c) = world.insert(
                        RigidBodyBuilder::dynamic()
                            .translation(at)
                            .linvel(Vector::new(1.0, 0.0, 0.0))
                            .angvel(Vector::new(0.0, 0.0, -1.0 / r))
                            .can_sleep(false),
                        ColliderBuilder::ball(r).density(1000.0).friction(MU),
                    );
                    hooked.push(c);
                }
            }
            Scene::Drum { .. }
            | Scene::Heightfield { .. }
            | Scene::Compounds { .. }
            | Scene::Platforms { .. }
            | Scene::Dominoes { .. }
            | Scene::Keva => {
                vib_host = examples::build(scene, &mut world, &mut hooked, &mut drivers);
            }
        }
        world.integration_parameters.dt = scene.dt();
        if variant == Variant::PlainCoulomb {
            world.integration_parameters.friction_model = FrictionModel::Coulomb;
        }
        let stepper = match variant {
            Variant::PlainSimplified | Variant::PlainCoulomb => Stepper::Plain,
            Variant::NoopHook => {
                for &h in &hooked {
                    let c = &mut world.colliders[h];
                    c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
                }
                Stepper::Noop(NoopHook)
            }
            _ => {
                let mut m = StickSlip::new(material_of(variant));
                for &h in &hooked {
                    m.attach(&mut world.colliders, h, None);
                }
                let mode = match variant {
                    Variant::EpVibResolved => Some((VibrationMode::TimeResolved, scene)),
                    Variant::EpVibAveraged => Some((VibrationMode::Averaged, scene)),
                    _ => None,
                };
                if let Some((mode, scene)) = mode {
                    let f = match mode {
                        VibrationMode::TimeResolved => scene.resolved_frequency(),
                        VibrationMode::Averaged => 20_000.0,
                    };
                    let source = VibrationSource::new(
                        VibrationDirection::Normal,
                        Amplitude::Ratio(0.3),
                        f,
                        Waveform::Sine,
                        0.0,
                        mode,
                    )
                    .unwrap();
                    m.set_vibration(vib_host, source);
                }
                Stepper::StickSlip(Box::new(m))
            }
        };
        Bench {
            world,
            stepper,
            drivers,
            time: 0.0,
            hooked,
        }
    }

    /// Builds and settles.
    pub fn settled(scene: Scene, variant: Variant, settle_steps: usize) -> Bench {
        let mut b = Bench::new(scene, variant);
        for _ in 0..settle_steps {
            b.step();
        }
        b
    }

    /// Of the colliders stickslip is attached to, how many it lets rapier recycle now, and
    /// how many there are (`None` for the variants without stickslip).
    pub fn recycled(&self) -> Option<(usize, usize)> {
        let Stepper::StickSlip(m) = &self.stepper else {
            return None;
        };
        let quiet = self.hooked.iter().filter(|&&h| m.is_recycled(h)).count();
        Some((quiet, self.hooked.len()))
    }

    /// One step (moves the kinematic driver first).
    #[inline]
    pub fn step(&mut self) {
        let dt = self.drive();
        match &mut self.stepper {
            Stepper::Plain => self.world.step(),
            Stepper::Noop(h) => self.world.step_with_events(&*h, &()),
            Stepper::StickSlip(m) => m.step(&mut self.world),
        }
        self.time += dt;
    }

    /// Moves the driven kinematic bodies to where the coming step takes them; returns dt.
    fn drive(&mut self) -> f64 {
        let dt = self.world.integration_parameters.dt as f64;
        for d in &self.drivers {
            let t = (self.time + dt) as f32;
            let s = (2.0 * std::f32::consts::PI * d.frequency * t).sin() * d.amplitude;
            let to = d.origin + d.direction * s;
            self.world.bodies[d.body].set_next_kinematic_translation(to);
        }
        dt
    }

    /// [`Self::step`], timed by `clock` in three phases: what stickslip does before rapier's
    /// step (`wake_driven`, `begin_step`, `resist_rotation`), rapier's step (with the hook
    /// inside), and what stickslip does after it (`end_step`: the pass that decides which
    /// contacts recycle, the sweep). The same calls as `StickSlip::step`; a plain or no-op
    /// world is all rapier.
    pub fn step_phases(
        &mut self,
        clock: impl Fn() -> std::time::Duration,
    ) -> [std::time::Duration; 3] {
        let dt = self.drive();
        let t0 = clock();
        let phases = match &mut self.stepper {
            Stepper::Plain => {
                self.world.step();
                [t0, t0, clock(), clock()]
            }
            Stepper::Noop(h) => {
                self.world.step_with_events(&*h, &());
                [t0, t0, clock(), clock()]
            }
            Stepper::StickSlip(m) => {
                let w = &mut self.world;
                m.wake_driven(&w.narrow_phase, &w.colliders, &mut w.bodies);
                m.begin_step(&w.integration_parameters, &w.bodies, &mut w.colliders);
                m.resist_rotation(
                    &w.integration_parameters,
                    &mut w.impulse_joints,
                    &w.narrow_phase,
                    &mut w.bodies,
                    &w.colliders,
                );
                let t1 = clock();
                w.step_with_events(&**m, &());
                let t2 = clock();
                m.end_step(&w.narrow_phase, &w.bodies, &mut w.colliders);
                [t0, t1, t2, clock()]
            }
        };
        self.time += dt;
        [
            phases[1] - phases[0],
            phases[2] - phases[1],
            phases[3] - phases[2],
        ]
    }

    /// (contact pairs rapier keeps, those with a touching manifold) after the last step.
    pub fn pairs(&self) -> (usize, usize) {
        let pairs = self.world.narrow_phase.contact_pairs();
        pairs.fold((0, 0), |(n, touching), p| {
            (n + 1, touching + usize::from(p.has_any_active_contact()))
        })
    }

    /// (manifolds with solver contacts, solver contact points, all manifolds rapier keeps —
    /// also those whose points are all beyond the contact prediction distance) after the last
    /// step.
    pub fn contacts(&self) -> (usize, usize, usize) {
        let (mut manifolds, mut points, mut all) = (0, 0, 0);
        for pair in self.world.narrow_phase.contact_pairs() {
            all += pair.manifolds().len();
            for m in pair.solver_manifolds() {
                if !m.data.solver_contacts.is_empty() {
                    manifolds += 1;
                    points += m.data.solver_contacts.len();
                }
            }
        }
        (manifolds, points, all)
    }

    /// The stickslip modifier, if this variant has one.
    pub fn modifier(&mut self) -> Option<&mut StickSlip> {
        match &mut self.stepper {
            Stepper::StickSlip(m) => Some(m),
            _ => None,
        }
    }

    /// Whether any dynamic body left the scene or became non-finite (a blow-up check).
    pub fn is_sane(&self) -> bool {
        self.world.bodies.iter().all(|(_, b)| {
            let p = b.translation();
            p.is_finite() && p.y > -5.0
        })
    }
}
