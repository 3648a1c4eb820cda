//! stickslip in an avian app, in a real window: three troughs of the same slope tan θ = 0.5,
//! five parts on each, the same start, and a lane of rolling balls.
//!
//! 1. **avian's `Friction::new(0.4)`**: what avian alone does with a material of static
//!    coefficient 0.6 and dynamic 0.4 (avian reads only the dynamic one): tan θ > 0.4, the
//!    parts slide at a = g (sin θ − μ_k cos θ). The HUD shows their measured acceleration.
//! 2. **The same material with its static coefficient,
//!    `Friction::new(0.4).with_static_coefficient(0.6)`, and `StickSlipAvianPlugin`**: tan θ is
//!    below μ_s = 0.6, the parts hold. The HUD shows how far they crept.
//! 3. **A vibrating conveyor**: an elasto-plastic stickslip material (μ0 = 0.8 for break-away
//!    and sliding, c = 2e4 1/m) holds on the slope; Popov's normal vibration of the trough
//!    (α = 0.6, 20 kHz, averaged) lowers its static coefficient to μ0 (1 − α) = 0.32 and the
//!    parts flow. They settle at the speed where the mean sliding friction
//!    μ0 (1 − α Ψ(β)) equals tan θ (Popov 2020, Eq. 33): the HUD shows it beside the measured
//!    speed.
//! 4. **Rolling resistance** (`FrictionMaterial::with_rolling`), on a lane of tan θ = 0.08: three
//!    balls side by side, the EP material without rolling resistance (rolls down at
//!    a = 5/7 g sin θ), with μ_r = 0.12 above tan θ (holds) and with μ_r = 0.04 below it (rolls
//!    at a = 5/7 g (sin θ − μ_r cos θ)). Balls are coloured by their rolling regime
//!    (`StickSlipRolling`: green held, red rolling, white without rolling resistance).
//!
//! Like with like: a part's speed (or acceleration) counts from the end of its start-up
//! transient to now, over parts that have not been restarted since; the HUD says "settling"
//! until the first parts are through it.
//!
//! Parts are coloured by the regime of their contacts (green sticking, orange stick-slip, red
//! sliding, white for avian's own contacts or in flight); the contact gizmos show each
//! contact's friction force and normal. Parts that reach the end of a trough start over where
//! they started (each its own place: on trough 1 they arrive at the end within a tenth of a
//! second of each other).
//!
//! Keys: V vibration on/off (trough 3), Space pause, S slow motion (×0.1), R reset,
//! G contact gizmos.
//!
//! ```sh
//! cargo run --release -p stickslip-avian --features window --example avian_conveyor
//! # No display: under Xvfb (software Vulkan), render 120 frames of 1/30 s simulated time
//! # each, save the window and exit.
//! xvfb-run -a -s "-screen 0 1280x720x24" cargo run -p stickslip-avian --features window \
//!     --example avian_conveyor -- --screenshot conveyor.png --frames 120
//! ```

use avian3d::prelude::*;
use bevy::prelude::*;
use stickslip_avian::debug::{StickSlipDebugPlugin, StickSlipGizmos, regime_color};
use stickslip_avian::window::{Hud, WindowedApp, caption, command_line, hud_box, time_keys};
use stickslip_avian::{
    FrictionMaterial, StickSlipAvianPlugin, StickSlipContacts, StickSlipFriction, StickSlipRolling,
    StickSlipVibration, VibrationSource,
};
use stickslip_core::contact::{Amplitude, VibrationDirection, VibrationMode};
use stickslip_core::law::{Law, Regime};
use stickslip_core::popov;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;

/// Slope tan θ of the three troughs.
const SLOPE: f32 = 0.5;
/// avian's `Friction` of troughs 1 and 2: dynamic and static coefficients.
const MU_K: f32 = 0.4;
const MU_S: f32 = 0.6;
/// The elasto-plastic material of trough 3: μ0 (break-away and sliding), stiffness c (1/m).
const MU0: f64 = 0.8;
const C: f64 = 2e4;
/// Popov vibration of trough 3: amplitude ratio α, frequency (Hz).
const ALPHA: f64 = 0.6;
const F_POPOV: f64 = 20_000.0;
/// Physics rate (Hz); avian solves each tick in its default 6 substeps.
const PHYSICS_HZ: f64 = 240.0;
const G: f32 = 9.81;
/// Slope tan θ of the rolling lane, its balls' radius (m), and their rolling resistance μ_r
/// (none, above tan θ, below it).
const ROLL_SLOPE: f32 = 0.08;
const BALL: f32 = 0.04;
const MU_R: [f64; 3] = [0.0, 0.12, 0.04];
/// The balls' places across the rolling lane (m from its centre line).
const ACROSS: [f32; 3] = [-0.15, 0.0, 0.15];
/// Trough centres along z, the troughs' length (m), the first part's start position along
/// them and where parts start over.
const LANES: [f32; 4] = [-0.8, 0.0, 0.8, 1.8];
const LENGTH: f32 = 3.0;
const START: f32 = -1.3;
const END: f32 = 1.3;
/// Parts per trough, their spacing along it (m) and half extent (m).
const PARTS: usize = 5;
const SPACING: f32 = 0.2;
const HALF: f32 = 0.04;
/// Start-up transient of a part (s of simulated time) before its speed counts: the contact
/// forms in a few ticks on troughs 1 and 2; on trough 3 the speed approaches Popov's v*
/// within a second or two (`tests/conveyor.rs`: 0.13 % below it from 2 s on; this HUD at 4 s,
/// counting from 1.5 s: 0.4 % below).
const SETTLE: [f64; 4] = [0.2, 0.2, 1.5, 0.2];

fn main() -> AppExit {
    let Some((shot, _)) = command_line("avian_conveyor [--screenshot PATH] [--frames N]", 120, 0)
    else {
        return AppExit::error();
    };
    let mut app = App::new();
    app.add_plugins(WindowedApp::new(
        "stickslip in avian: static friction and a vibrating conveyor",
    ))
    .add_plugins((
        PhysicsPlugins::default(),
        StickSlipAvianPlugin::default(),
        StickSlipDebugPlugin,
    ))
    .insert_resource(Time::<Fixed>::from_hz(PHYSICS_HZ))
    .insert_resource(Theory::compute())
    .add_systems(Startup, (setup, spawn_parts).chain())
    .add_systems(
        FixedPostUpdate,
        (tally_regimes, measure, restart_parts).after(PhysicsSystems::Writeback),
    )
    .add_systems(
        Update,
        (
            keys,
            time_keys,
            colour_parts,
            hud,
            place_labels,
            vibration_cue,
        ),
    );
    if let Some(shot) = shot {
        // Reproducible pictures: the window at a given frame, every frame 1/30 s.
        app.add_plugins(shot);
    }
    app.run()
}

/// What the closed forms and Popov's theory say the troughs do.
#[derive(Resource)]
struct Theory {
    /// Trough 1's acceleration under Coulomb friction at μ_k (m/s²).
    slide: f32,
    /// Popov's conveying speed of trough 3 (m/s).
    popov: f64,
    /// The rolling balls' accelerations (m/s²; 0 for the one held).
    rolling: [f32; 3],
}

impl Theory {
    fn compute() -> Theory {
        let theta = SLOPE.atan();
        // μ0 (1 − α Ψ(β*)) = tan θ, β* = c v*/(μ0 α f).
        let target = (1.0 - SLOPE as f64 / MU0) / ALPHA;
        let beta = popov::beta_at_psi(&Waveform::Sine, target).unwrap_or(f64::NAN);
        let roll = ROLL_SLOPE.atan();
        Theory {
            slide: G * (theta.sin() - MU_K * theta.cos()),
            popov: beta * MU0 * ALPHA * F_POPOV / C,
            rolling: MU_R.map(|mu_r| {
                let mu_r = mu_r as f32;
                // A solid ball rolls at 5/7 of a sliding point's acceleration.
                (5.0 / 7.0 * G * (roll.sin() - mu_r * roll.cos())).max(0.0)
            }),
        }
    }
}

/// A part: its trough (0, 1 or 2; 3 the rolling lane), start position along it (m), and on
/// the rolling lane its ball (0, 1, 2).
#[derive(Component)]
#[require(RegimeTally, Shown, Run)]
struct Part {
    lane: usize,
    home: f32,
    ball: usize,
}

/// A part's run since it was (re)started: when, and its state along the trough once the
/// start-up transient was over and after the last tick.
#[derive(Component, Default)]
struct Run {
    started: f64,
    first: Option<Sample>,
    last: Option<Sample>,
}

/// Time (s), position along the trough (m) and speed along it (m/s).
#[derive(Clone, Copy)]
struct Sample {
    t: f64,
    along: f32,
    speed: f32,
}

impl Run {
    fn restart(&mut self, now: f64) {
        *self = Run {
            started: now,
            ..default()
        };
    }

    /// (speed, acceleration) over the settled part of the run, if it has one.
    fn rates(&self) -> Option<(f32, f32)> {
        let (a, b) = (self.first?, self.last?);
        let dt = (b.t - a.t) as f32;
        (dt > 0.0).then(|| ((b.along - a.along) / dt, (b.speed - a.speed) / dt))
    }
}

/// How many ticks since the last frame a part spent sticking, in stick-slip, sliding or
/// without contact: its colour is the regime of most of them.
#[derive(Component, Default)]
struct RegimeTally([u32; 4]);

/// The regime a part is shown in (0 sticking, 1 stick-slip, 2 sliding, 3 none): the HUD counts
/// the parts as the picture shows them (a part asleep keeps its regime; avian reads back only
/// the contacts it solved).
#[derive(Component, Default)]
struct Shown(usize);

/// The base of trough 3 (carries the Popov vibration).
#[derive(Component)]
struct PopovBase;

/// Trough `i`'s label, placed beside it on screen.
#[derive(Component)]
struct LaneLabel(usize);

/// Materials and mesh shared by the parts.
#[derive(Resource)]
struct Palette {
    airborne: Handle<StandardMaterial>,
    regimes: [Handle<StandardMaterial>; 3],
    part: Handle<Mesh>,
    ball: Handle<Mesh>,
}

/// Downhill direction and the trough's pose.
fn lane_frame(lane: usize) -> (Vec3, Quat, Vec3) {
    let slope = if lane == 3 { ROLL_SLOPE } else { SLOPE };
    let tilt = Quat::from_rotation_z(-slope.atan());
    (tilt * Vec3::X, tilt, Vec3::new(0.0, 0.0, LANES[lane]))
}

/// A point at `along` metres on trough `lane`, `up` metres above its surface.
fn on_lane(lane: usize, along: f32, up: f32) -> Vec3 {
    on_lane_at(lane, along, up, 0.0)
}

/// As [`on_lane`], `across` metres from the trough's centre line.
fn on_lane_at(lane: usize, along: f32, up: f32, across: f32) -> Vec3 {
    let (_, rotation, centre) = lane_frame(lane);
    centre + rotation * Vec3::new(along, 0.05 + up, across)
}

/// The rolling lane's friction (the EP material of trough 3, no vibration) and a ball's, with
/// its rolling resistance μ_r (a sharp elasto-plastic law) above 0.
fn rolling_material(mu_r: f64) -> StickSlipFriction {
    let sharp = |mu: f64| {
        let curve = Curve::constant(mu).expect("positive");
        Law::elasto_plastic(C, mu, mu, curve).expect("valid law")
    };
    let material = FrictionMaterial::new(sharp(MU0));
    StickSlipFriction(Some(if mu_r > 0.0 {
        material.with_rolling(sharp(mu_r))
    } else {
        material
    }))
}

/// Trough `lane`'s friction and its parts': avian's `Friction` without and with its static
/// coefficient, or stickslip's elasto-plastic material.
fn lane_friction(lane: usize) -> (Friction, Option<StickSlipFriction>) {
    match lane {
        0 => (Friction::new(MU_K), None),
        1 => (Friction::new(MU_K).with_static_coefficient(MU_S), None),
        3 => (Friction::default(), Some(rolling_material(0.0))),
        _ => {
            let curve = Curve::constant(MU0).expect("positive");
            let law = Law::elasto_plastic(C, MU0, MU0, curve).expect("valid law");
            (
                Friction::default(),
                Some(StickSlipFriction(Some(FrictionMaterial::new(law)))),
            )
        }
    }
}

fn popov_vibration() -> StickSlipVibration {
    StickSlipVibration(
        VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(ALPHA),
            F_POPOV,
            Waveform::Sine,
            0.0,
            VibrationMode::Averaged,
        )
        .expect("valid source"),
    )
}

fn setup(
    mut commands: Commands,
    mut gizmos: ResMut<GizmoConfigStore>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    // Contact gizmos sized for 8 cm parts of 0.5 kg: arrows of 6 cm per newton.
    let (config, contacts) = gizmos.config_mut::<StickSlipGizmos>();
    config.line.width = 3.0;
    contacts.force_scale = 0.06;
    contacts.normal_length = 0.08;
    contacts.point_radius = 0.012;
    commands.spawn((
        Camera3d::default(),
        Transform::from_xyz(0.45, 2.9, 4.4).looking_at(Vec3::new(0.45, 0.0, 0.2), Vec3::Y),
    ));
    commands.spawn((
        DirectionalLight {
            illuminance: 8000.0,
            shadow_maps_enabled: true,
            ..default()
        },
        Transform::from_xyz(-2.0, 6.0, 3.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    let mut flat = |c: Color| {
        materials.add(StandardMaterial {
            base_color: c,
            perceptual_roughness: 0.7,
            ..default()
        })
    };
    let metal = flat(Color::srgb(0.45, 0.48, 0.55));
    let shaker = flat(Color::srgb(0.3, 0.5, 0.85));
    let avian = flat(Color::srgb(0.55, 0.42, 0.3));
    let rolling = flat(Color::srgb(0.35, 0.55, 0.4));
    commands.insert_resource(Palette {
        airborne: flat(Color::WHITE),
        regimes: [
            flat(regime_color(Regime::Sticking)),
            flat(regime_color(Regime::StickSlip)),
            flat(regime_color(Regime::Sliding)),
        ],
        part: meshes.add(Cuboid::from_length(2.0 * HALF)),
        ball: meshes.add(Sphere::new(BALL)),
    });
    let base_mesh = meshes.add(Cuboid::new(LENGTH, 0.1, 0.5));
    let wall_mesh = meshes.add(Cuboid::new(LENGTH, 0.12, 0.02));
    for lane in 0..4 {
        let (_, rotation, centre) = lane_frame(lane);
        let (friction, material) = lane_friction(lane);
        let mut base = commands.spawn((
            Mesh3d(base_mesh.clone()),
            MeshMaterial3d(
                [
                    avian.clone(),
                    metal.clone(),
                    shaker.clone(),
                    rolling.clone(),
                ][lane]
                    .clone(),
            ),
            RigidBody::Static,
            Collider::cuboid(LENGTH, 0.1, 0.5),
            friction,
            Transform::from_translation(centre).with_rotation(rotation),
        ));
        if let Some(material) = material {
            base.insert(material);
        }
        if lane == 2 {
            base.insert((PopovBase, popov_vibration()));
        }
        let trough = base.id();
        // Side walls as children: part of the trough's body, avian's friction (low).
        for side in [-1.0, 1.0] {
            commands.spawn((
                Mesh3d(wall_mesh.clone()),
                MeshMaterial3d(metal.clone()),
                Collider::cuboid(LENGTH, 0.12, 0.02),
                Friction::new(0.05),
                Transform::from_xyz(0.0, 0.11, side * 0.26),
                ChildOf(trough),
            ));
        }
        let title = [
            format!("1  avian alone: Friction {MU_K}\n   (static {MU_S} not read)"),
            format!("2  stickslip: Friction {MU_K},\n   static {MU_S}"),
            format!(
                "3  stickslip EP mu0 {MU0}, Popov\n   normal vibration a {ALPHA}, {} kHz",
                F_POPOV / 1000.0
            ),
            format!(
                "4  rolling resistance, tan {ROLL_SLOPE}:\n   mu_r none / {} / {}",
                MU_R[1], MU_R[2]
            ),
        ][lane]
            .clone();
        commands.spawn((LaneLabel(lane), caption(title)));
    }
    commands.spawn(hud_box());
}

/// Five parts per trough at its upper end, at rest, with the trough's friction; three balls
/// side by side at the rolling lane's.
fn spawn_parts(mut commands: Commands, palette: Res<Palette>, time: Res<Time<Fixed>>) {
    let (_, rotation, _) = lane_frame(3);
    for (ball, mu_r) in MU_R.into_iter().enumerate() {
        commands.spawn((
            Part {
                lane: 3,
                home: START,
                ball,
            },
            Run {
                started: time.elapsed_secs_f64(),
                ..default()
            },
            Mesh3d(palette.ball.clone()),
            MeshMaterial3d(palette.airborne.clone()),
            RigidBody::Dynamic,
            Collider::sphere(BALL),
            rolling_material(mu_r),
            SleepingDisabled,
            Transform::from_translation(on_lane_at(3, START, BALL, ACROSS[ball]))
                .with_rotation(rotation),
        ));
    }
    for lane in 0..3 {
        let (_, rotation, _) = lane_frame(lane);
        for k in 0..PARTS {
            let along = START + SPACING * k as f32;
            let (friction, material) = lane_friction(lane);
            let mut part = commands.spawn((
                Part {
                    lane,
                    home: along,
                    ball: 0,
                },
                Run {
                    started: time.elapsed_secs_f64(),
                    ..default()
                },
                Mesh3d(palette.part.clone()),
                MeshMaterial3d(palette.airborne.clone()),
                RigidBody::Dynamic,
                Collider::cuboid(2.0 * HALF, 2.0 * HALF, 2.0 * HALF),
                friction,
                // Point-mass-like, as the closed forms.
                LockedAxes::ROTATION_LOCKED,
                Transform::from_translation(on_lane(lane, along, HALF)).with_rotation(rotation),
            ));
            if let Some(material) = material {
                part.insert(material);
            }
        }
    }
}

/// After every tick: each part's position and speed along its trough, once its start-up
/// transient is over.
fn measure(time: Res<Time>, mut parts: Query<(&Part, &Position, &LinearVelocity, &mut Run)>) {
    let t = time.elapsed_secs_f64();
    for (part, position, velocity, mut run) in &mut parts {
        if t - run.started < SETTLE[part.lane] {
            continue;
        }
        let (dir, _, centre) = lane_frame(part.lane);
        let sample = Sample {
            t,
            along: (position.0 - centre).dot(dir),
            speed: velocity.0.dot(dir),
        };
        if run.first.is_none() {
            run.first = Some(sample);
        }
        run.last = Some(sample);
    }
}

/// A part past the end of its trough starts over where it started, at rest, with a new run.
fn restart_parts(
    time: Res<Time>,
    mut parts: Query<(
        &Part,
        &mut Position,
        &mut Transform,
        &mut LinearVelocity,
        &mut AngularVelocity,
        &mut Run,
    )>,
) {
    for (part, mut position, mut transform, mut velocity, mut spin, mut run) in &mut parts {
        let (dir, _, centre) = lane_frame(part.lane);
        if (position.0 - centre).dot(dir) > END {
            position.0 = if part.lane == 3 {
                on_lane_at(3, part.home, BALL + 0.002, ACROSS[part.ball])
            } else {
                on_lane(part.lane, part.home, HALF + 0.002)
            };
            transform.translation = position.0;
            velocity.0 = Vec3::ZERO;
            spin.0 = Vec3::ZERO;
            run.restart(time.elapsed_secs_f64());
        }
    }
}

#[allow(clippy::too_many_arguments)]
fn keys(
    mut commands: Commands,
    keys: Res<ButtonInput<KeyCode>>,
    fixed: Res<Time<Fixed>>,
    mut gizmos: ResMut<GizmoConfigStore>,
    popov_base: Query<(Entity, Has<StickSlipVibration>), With<PopovBase>>,
    mut parts: Query<(Entity, &Part, &mut Run)>,
) {
    if keys.just_pressed(KeyCode::KeyV) {
        for (e, on) in &popov_base {
            if on {
                commands.entity(e).remove::<StickSlipVibration>();
            } else {
                commands.entity(e).insert(popov_vibration());
            }
        }
        // Trough 3's parts start a new run: the old one measured the other regime.
        for (_, part, mut run) in &mut parts {
            if part.lane == 2 {
                run.restart(fixed.elapsed_secs_f64());
            }
        }
    }
    if keys.just_pressed(KeyCode::KeyG) {
        gizmos.config_mut::<StickSlipGizmos>().0.enabled ^= true;
    }
    if keys.just_pressed(KeyCode::KeyR) {
        for (e, _, _) in &parts {
            commands.entity(e).despawn();
        }
        commands.run_system_cached(spawn_parts);
    }
}

/// Counts each part's regime (the most slippery of its contacts) after every tick; a part
/// asleep is not solved and keeps its colour.
fn tally_regimes(
    contacts: Res<StickSlipContacts>,
    rolling: Res<StickSlipRolling>,
    mut parts: Query<(Entity, &Part, &mut RegimeTally), Without<Sleeping>>,
) {
    for (e, part, mut tally) in &mut parts {
        // A ball: the regime of its rolling resistance (none without it).
        let regime = if part.lane == 3 {
            rolling.of(e).find_map(|r| r.rolling)
        } else {
            contacts.regime_of(e)
        };
        let i = match regime {
            Some(Regime::Sticking) => 0,
            Some(Regime::StickSlip) => 1,
            Some(Regime::Sliding) => 2,
            None => 3,
        };
        tally.0[i] += 1;
    }
}

/// A part's colour: the regime of most ticks since the last frame; white in flight and for
/// avian's own pairs (trough 1), which have no regime.
fn colour_parts(
    palette: Res<Palette>,
    mut parts: Query<(
        &mut RegimeTally,
        &mut Shown,
        &mut MeshMaterial3d<StandardMaterial>,
    )>,
) {
    for (mut tally, mut shown, mut material) in &mut parts {
        if tally.0 == [0; 4] {
            continue; // no tick since the last frame
        }
        let most = (0..4).max_by_key(|i| (tally.0[*i], *i)).unwrap_or(3);
        tally.0 = [0; 4];
        shown.0 = most;
        let handle = match most {
            0..=2 => &palette.regimes[most],
            _ => &palette.airborne,
        };
        if material.0 != *handle {
            material.0 = handle.clone();
        }
    }
}

/// Trough `lane`'s mean (speed, acceleration) over its parts' settled runs, and how many
/// parts count.
fn lane_rates(parts: &Query<(&Part, &Run)>, lane: usize) -> Option<(f32, f32, usize)> {
    ball_rates(parts, lane, None)
}

/// As [`lane_rates`], of one ball of the lane (or all of its parts).
fn ball_rates(
    parts: &Query<(&Part, &Run)>,
    lane: usize,
    ball: Option<usize>,
) -> Option<(f32, f32, usize)> {
    let rates: Vec<(f32, f32)> = parts
        .iter()
        .filter(|(p, _)| p.lane == lane && ball.is_none_or(|b| b == p.ball))
        .filter_map(|(_, run)| run.rates())
        .collect();
    let n = rates.len();
    (n > 0).then(|| {
        let (v, a) = rates
            .iter()
            .fold((0.0, 0.0), |(v, a), (dv, da)| (v + dv, a + da));
        (v / n as f32, a / n as f32, n)
    })
}

fn hud(
    time: Res<Time<Virtual>>,
    fixed: Res<Time<Fixed>>,
    theory: Res<Theory>,
    parts: Query<(&Part, &Run)>,
    shown: Query<&Shown>,
    popov_base: Query<Has<StickSlipVibration>, With<PopovBase>>,
    mut text: Query<&mut Text, With<Hud>>,
) {
    let Ok(mut text) = text.single_mut() else {
        return;
    };
    let on = popov_base.iter().any(|on| on);
    let state = match (time.is_paused(), time.relative_speed() < 1.0) {
        (true, _) => "   [paused]",
        (false, true) => "   [slow motion x0.1]",
        _ => "",
    };
    let settling = |lane: usize| format!("settling ({} s)", SETTLE[lane]);
    let slide =
        lane_rates(&parts, 0).map_or(settling(0), |(_, a, n)| format!("a {a:+.3} m/s2 ({n})"));
    let hold = lane_rates(&parts, 1).map_or(settling(1), |(v, _, n)| {
        format!("{:+.3} mm/s ({n})", 1000.0 * v)
    });
    let conveyed =
        lane_rates(&parts, 2).map_or(settling(2), |(v, _, n)| format!("{v:+.3} m/s ({n})"));
    let popov = if on {
        format!("{:.3} m/s  Popov: mu0 (1 - a Psi(b*)) = tan", theory.popov)
    } else {
        "0          (vibration off: EP holds)".into()
    };
    let ball = |b: usize| {
        ball_rates(&parts, 3, Some(b)).map_or("settling".to_string(), |(v, a, _)| {
            if b == 1 {
                format!("{:+.2} mm/s", 1000.0 * v)
            } else {
                format!("a {a:+.3}")
            }
        })
    };
    let rolls = format!("{} | {} | {}", ball(0), ball(1), ball(2));
    let mut regimes = [0usize; 4];
    for s in &shown {
        regimes[s.0.min(3)] += 1;
    }
    text.0 = format!(
        "stickslip in avian    t = {t:.2} s    slope tan {SLOPE}    vibration {vib}{state}\n\
         \n\
         trough                   measured (parts)     theory\n\
         1  avian alone           {slide:<20} a {a:.3} m/s2  g (sin - {MU_K} cos): slides\n\
         2  stickslip, static     {hold:<20} 0  holds: tan {SLOPE} < mu_s {MU_S}\n\
         3  Popov vibration       {conveyed:<20} {popov}\n\
         4  rolling: none|held|mu_r  {rolls}   theory a {r0:.3} | 0 | {r2:.3}: 5/7 g (sin - mu_r cos)\n\
         \n\
         parts   {st} sticking, {ss} stick-slip, {sl} sliding, {no} without stickslip contact\n\
         colours green sticking, orange stick-slip, red sliding, white avian's own\n\
         keys    V vibration  Space pause  S slow motion  R reset  G gizmos",
        t = fixed.elapsed_secs_f64(),
        vib = if on { "ON" } else { "OFF" },
        a = theory.slide,
        r0 = theory.rolling[0],
        r2 = theory.rolling[2],
        st = regimes[0],
        ss = regimes[1],
        sl = regimes[2],
        no = regimes[3],
    );
}

/// Keeps each trough's label beside its lower end on screen.
fn place_labels(
    camera: Single<(&Camera, &GlobalTransform)>,
    mut labels: Query<(&LaneLabel, &mut Node)>,
) {
    let (camera, at) = *camera;
    for (label, mut node) in &mut labels {
        let anchor = on_lane(label.0, LENGTH / 2.0 + 0.05, 0.0) + Vec3::new(0.0, 0.0, 0.2);
        if let Ok(p) = camera.world_to_viewport(at, anchor) {
            node.left = px(p.x);
            node.top = px(p.y);
        }
    }
}

/// 20 kHz cannot be seen: a wave drawn under the vibrating base says it is on.
fn vibration_cue(
    time: Res<Time>,
    base: Query<&Transform, (With<PopovBase>, With<StickSlipVibration>)>,
    mut gizmos: Gizmos,
) {
    let phase = time.elapsed_secs() * 6.0;
    for transform in &base {
        let points = (0..=120).map(|i| {
            let x = -LENGTH / 2.0 + LENGTH * i as f32 / 120.0;
            let y = -0.08 + 0.02 * (x * 25.0 - phase).sin();
            transform.transform_point(Vec3::new(x, y, 0.26))
        });
        gizmos.linestrip(points, Color::srgb(0.4, 0.7, 1.0));
    }
}
