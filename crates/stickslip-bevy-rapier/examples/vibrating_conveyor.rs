//! Vibration moves parts that friction holds: three lanes side by side in a real window, the
//! same five parts on each, the same start.
//!
//! 1. **Inclined trough, no vibration.** Slope tan θ = 0.3 under elasto-plastic friction
//!    (μ0 = 0.5 for break-away and sliding, c = 2e4 1/m): the law holds the parts, without
//!    creep (at most g_ba = μ0/c = 25 µm).
//! 2. **The same trough with Popov's normal vibration** of its base (α = 0.6, 20 kHz,
//!    averaged): the static coefficient drops to μ0 (1 − α) = 0.2 < 0.3 and the parts flow.
//!    They settle where the mean sliding friction μ0 (1 − α Ψ(β)) equals the slope; the HUD
//!    shows their measured transport speed beside that speed of the theory.
//! 3. **A classic vibratory feeder**: a horizontal kinematic trough vibrating 3 mm at 15 Hz
//!    along a 30° throw angle (throw number Γ = 1.36 > 1): the parts hop forward. The HUD
//!    shows the point-mass reference of `stickslip_theory::feeder` beside the measured speed.
//!
//! Like with like: a part's speed counts from the end of its start-up transient to now (on
//! lane 3 over whole drive periods), over parts that have not been restarted since; the HUD
//! says "settling" until the first parts are through it.
//!
//! Parts are coloured by the regime of their contacts (green sticking, orange stick-slip, red
//! sliding, white in flight); the contact gizmos show each contact's friction force (arrow in
//! the regime's colour) and normal (white). Parts that reach the end of a lane start over.
//!
//! Keys: V vibration on/off (lanes 2 and 3), Space pause, S slow motion (×0.1), R reset,
//! G contact gizmos.
//!
//! A bevy_rapier app: bevy_rapier's `RapierPhysicsPlugin` in the fixed schedule at 3 kHz,
//! its components (`RigidBody`, `Collider`, `Friction`, `LockedAxes`, child colliders, a
//! kinematic position-based trough), and stickslip added with `StickSlipRapierPlugin` and a
//! `StickSlipFriction` / `StickSlipVibration` component on the troughs and parts.
//!
//! ```sh
//! cargo run --release -p stickslip-bevy-rapier --features window --example vibrating_conveyor
//! # No display: under Xvfb (software Vulkan), render 120 frames of 1/30 s simulated time
//! # each, save the window and exit.
//! xvfb-run -a -s "-screen 0 1280x720x24" cargo run -p stickslip-bevy-rapier --features window \
//!     --example vibrating_conveyor -- --screenshot conveyor.png --frames 120
//! ```

use bevy::prelude::*;
use bevy::transform::systems::mark_dirty_trees;
use bevy_rapier3d::plugin::RapierTransformPropagateSet;
use bevy_rapier3d::prelude::*;
use std::f32::consts::FRAC_PI_6;
use stickslip_bevy_rapier::debug::{StickSlipDebugPlugin, StickSlipGizmos, regime_color};
use stickslip_bevy_rapier::window::{Hud, WindowedApp, caption, command_line, hud_box, time_keys};
use stickslip_bevy_rapier::{
    StickSlipContacts, StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin,
    StickSlipVibration,
};
use stickslip_core::law::{Law, Regime};
use stickslip_core::popov;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;
use stickslip_rapier_035::{
    Amplitude, FrictionMaterial, VibrationDirection, VibrationMode, VibrationSource,
};
use stickslip_theory::feeder::VibratoryFeeder;

/// Slope tan θ of lanes 1 and 2.
const SLOPE: f64 = 0.3;
/// Friction coefficient μ0 (break-away and sliding).
const MU0: f64 = 0.5;
/// Law stiffness c (1/m).
const C: f64 = 2e4;
/// Popov vibration of lane 2: amplitude ratio α, frequency (Hz).
const ALPHA: f64 = 0.6;
const F_POPOV: f64 = 20_000.0;
/// Vibratory feeder of lane 3: amplitude (m), frequency (Hz), throw angle (rad).
const FEEDER: (f32, f32, f32) = (0.003, 15.0, FRAC_PI_6);
/// Physics rate (Hz): 200 steps per feeder period.
const PHYSICS_HZ: f64 = 3000.0;
/// Lane centres along z, and the lanes' length (m) and the parts' start and restart
/// positions along them.
const LANES: [f32; 3] = [-0.8, 0.0, 0.8];
const LENGTH: f32 = 3.0;
const START: f32 = -1.3;
const END: f32 = 1.3;
/// Parts per lane and their spacing along the lane (m).
const PARTS: usize = 5;
const SPACING: f32 = 0.2;
/// Half extent of a part (m).
const HALF: f32 = 0.04;
/// Start-up transient of a part (s of simulated time) before its speed counts: lane 1's
/// contacts form in a few steps; on lane 2 the speed approaches Popov's v* as exp(−t/τ),
/// τ ≈ 0.35 s here, and is within 1.5 % of it after 1.5 s; lane 3's parts hop at their
/// steady mean speed after ~0.3 s (6 drive periods).
const SETTLE: [f64; 3] = [0.2, 1.5, 0.4];
/// Physics steps between a lane's speed samples: every step, and on lane 3 one drive period
/// (a hopping part's mean speed is its displacement over whole periods).
const SAMPLE_STEPS: [u64; 3] = [1, 1, (PHYSICS_HZ / FEEDER.1 as f64) as u64];

fn main() -> AppExit {
    let Some((shot, _)) = command_line(
        "vibrating_conveyor [--screenshot PATH] [--frames N]",
        120,
        0,
    ) else {
        return AppExit::error();
    };
    let mut app = App::new();
    app.add_plugins(WindowedApp::new("stickslip: vibrating conveyor"))
        // bevy_rapier in the fixed schedule, one rapier step per tick; stickslip beside it.
        .insert_resource(TimestepMode::Fixed {
            dt: (1.0 / PHYSICS_HZ) as f32,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default().in_fixed_schedule())
        .add_plugins(StickSlipRapierPlugin::default().in_fixed_schedule())
        .add_plugins(StickSlipDebugPlugin)
        .insert_resource(Time::<Fixed>::from_hz(PHYSICS_HZ))
        .insert_resource(Theory::compute())
        .add_systems(Startup, (setup, spawn_parts).chain())
        // Before the step (bevy_rapier's in FixedPostUpdate): the trough's target, restarts.
        .add_systems(FixedUpdate, (drive_feeder, restart_parts))
        // bevy_rapier 0.36 propagates transforms itself before each fixed step, but without
        // bevy's `mark_dirty_trees`: a body with children (the trough and its walls) then has a
        // GlobalTransform, hence a kinematic target, updated once per frame, not per step — at
        // 100 steps a frame the trough would jerk once per frame and the parts hop at 0.12 m/s
        // instead of 0.146.
        .add_systems(
            FixedPostUpdate,
            mark_dirty_trees.before(RapierTransformPropagateSet),
        )
        .add_systems(
            FixedPostUpdate,
            (tally_regimes, measure).after(PhysicsSet::Writeback),
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

/// What the theories say the lanes do.
#[derive(Resource)]
struct Theory {
    /// Popov's conveying speed of lane 2 (m/s).
    popov: f64,
    /// The point-mass reference speed of lane 3 (m/s) and its throw number.
    feeder: f64,
    throw_number: f64,
}

impl Theory {
    fn compute() -> Theory {
        // μ0 (1 − α Ψ(β*)) = tan θ, β* = c v*/(μ0 α f).
        let target = (1.0 - SLOPE / MU0) / ALPHA;
        let beta = popov::beta_at_psi(&Waveform::Sine, target).unwrap_or(f64::NAN);
        let (a, f, throw) = FEEDER;
        let feeder = VibratoryFeeder::new(a as f64, f as f64, throw as f64, MU0, 9.81)
            .expect("valid feeder");
        Theory {
            popov: beta * MU0 * ALPHA * F_POPOV / C,
            feeder: feeder.transport_speed(20, 20),
            throw_number: feeder.throw_number(),
        }
    }
}

/// A part, on lane 0, 1 or 2.
#[derive(Component)]
#[require(RegimeTally, Run)]
struct Part(usize);

/// A part's run since it was (re)started: when, and (time, position along the lane) at the
/// first sample after its start-up transient and at the last one.
#[derive(Component, Default)]
struct Run {
    started: f64,
    first: Option<(f64, f32)>,
    last: Option<(f64, f32)>,
}

impl Run {
    fn restart(&mut self, now: f64) {
        *self = Run {
            started: now,
            ..default()
        };
    }

    /// Mean speed along the lane over the settled part of the run, if it has one.
    fn speed(&self) -> Option<f32> {
        let ((t0, x0), (t1, x1)) = (self.first?, self.last?);
        (t1 > t0).then(|| (x1 - x0) / (t1 - t0) as f32)
    }
}

/// How many physics steps since the last frame a part spent sticking, in stick-slip, sliding
/// or without contact: a frame spans many steps (100 at 30 frames/s), so its colour is the
/// regime of most of them, not of whichever step came last.
#[derive(Component, Default)]
struct RegimeTally([u32; 4]);

/// The base of lane 2 (carries the Popov vibration).
#[derive(Component)]
struct PopovBase;

/// The kinematic trough of lane 3, vibrating about `rest` while `on`.
#[derive(Component)]
struct FeederTrough {
    rest: Vec3,
    on: bool,
}

/// Lane `i`'s label, placed over the lane on screen.
#[derive(Component)]
struct LaneLabel(usize);

/// Materials and meshes shared by the parts.
#[derive(Resource)]
struct Palette {
    airborne: Handle<StandardMaterial>,
    regimes: [Handle<StandardMaterial>; 3],
    part: Handle<Mesh>,
}

/// Lane `lane`'s mean speed over its parts' settled runs (m/s), and how many parts count.
fn lane_speed(parts: &Query<(&Part, &Run)>, lane: usize) -> Option<(f32, usize)> {
    let speeds: Vec<f32> = parts
        .iter()
        .filter(|(p, _)| p.0 == lane)
        .filter_map(|(_, run)| run.speed())
        .collect();
    let n = speeds.len();
    (n > 0).then(|| (speeds.iter().sum::<f32>() / n as f32, n))
}

/// Downhill (lanes 1, 2) or forward (lane 3) direction, and the lane's pose.
fn lane_frame(lane: usize) -> (Vec3, Quat, Vec3) {
    let z = LANES[lane];
    if lane < 2 {
        let tilt = Quat::from_rotation_z(-(SLOPE as f32).atan());
        (tilt * Vec3::X, tilt, Vec3::new(0.0, 0.0, z))
    } else {
        (Vec3::X, Quat::IDENTITY, Vec3::new(0.0, -0.45, z))
    }
}

/// A point at `along` metres on lane `lane`, `up` metres above its surface.
fn on_lane(lane: usize, along: f32, up: f32) -> Vec3 {
    let (_, rotation, centre) = lane_frame(lane);
    centre + rotation * Vec3::new(along, 0.05 + up, 0.0)
}

fn ep_material() -> FrictionMaterial {
    let curve = Curve::constant(MU0).expect("positive");
    FrictionMaterial::new(Law::elasto_plastic(C, MU0, MU0, curve).expect("valid law"))
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
    theory: Res<Theory>,
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
        Transform::from_xyz(0.45, 2.35, 3.4).looking_at(Vec3::new(0.45, 0.0, -0.2), Vec3::Y),
    ));
    commands.spawn((
        DirectionalLight {
            illuminance: 8000.0,
            shadow_maps_enabled: true,
            ..default()
        },
        Transform::from_xyz(-2.0, 6.0, 3.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    let metal = materials.add(StandardMaterial {
        base_color: Color::srgb(0.45, 0.48, 0.55),
        perceptual_roughness: 0.6,
        ..default()
    });
    let shaker = materials.add(StandardMaterial {
        base_color: Color::srgb(0.3, 0.5, 0.85),
        perceptual_roughness: 0.5,
        ..default()
    });
    let mut flat = |c: Color| {
        materials.add(StandardMaterial {
            base_color: c,
            perceptual_roughness: 0.8,
            ..default()
        })
    };
    commands.insert_resource(Palette {
        airborne: flat(Color::WHITE),
        regimes: [
            flat(regime_color(Regime::Sticking)),
            flat(regime_color(Regime::StickSlip)),
            flat(regime_color(Regime::Sliding)),
        ],
        part: meshes.add(Cuboid::from_length(2.0 * HALF)),
    });
    let base_mesh = meshes.add(Cuboid::new(LENGTH, 0.1, 0.5));
    let wall_mesh = meshes.add(Cuboid::new(LENGTH, 0.12, 0.02));
    for lane in 0..3 {
        let (_, rotation, centre) = lane_frame(lane);
        let mut base = commands.spawn((
            Mesh3d(base_mesh.clone()),
            MeshMaterial3d(if lane == 0 {
                metal.clone()
            } else {
                shaker.clone()
            }),
            Collider::cuboid(LENGTH / 2.0, 0.05, 0.25),
            StickSlipFriction(Some(ep_material())),
            Transform::from_translation(centre).with_rotation(rotation),
        ));
        match lane {
            0 => base.insert(RigidBody::Fixed),
            1 => base.insert((RigidBody::Fixed, PopovBase, popov_vibration())),
            _ => base.insert((
                RigidBody::KinematicPositionBased,
                FeederTrough {
                    rest: centre,
                    on: true,
                },
            )),
        };
        let trough = base.id();
        // Side walls as children: part of the trough's body, plain rapier friction (low).
        for side in [-1.0, 1.0] {
            commands.spawn((
                Mesh3d(wall_mesh.clone()),
                MeshMaterial3d(metal.clone()),
                Collider::cuboid(LENGTH / 2.0, 0.06, 0.01),
                Friction::coefficient(0.05),
                Transform::from_xyz(0.0, 0.11, side * 0.26),
                ChildOf(trough),
            ));
        }
        let (a, f, throw) = FEEDER;
        let title = [
            format!("1  no vibration\n   slope {SLOPE}, EP mu0 {MU0}"),
            format!(
                "2  Popov normal vibration\n   a {ALPHA}, {} kHz, averaged",
                F_POPOV / 1000.0
            ),
            format!(
                "3  vibratory feeder\n   {} mm, {f} Hz, {:.0} deg, G {:.2}",
                a * 1000.0,
                throw.to_degrees(),
                theory.throw_number
            ),
        ][lane]
            .clone();
        commands.spawn((LaneLabel(lane), caption(title)));
    }
    commands.spawn(hud_box());
}

/// Five parts per lane at the lanes' upper (or rear) end, at rest.
fn spawn_parts(mut commands: Commands, palette: Res<Palette>, time: Res<Time<Fixed>>) {
    for lane in 0..3 {
        let (_, rotation, _) = lane_frame(lane);
        for k in 0..PARTS {
            let along = START + SPACING * k as f32;
            commands.spawn((
                Part(lane),
                Run {
                    started: time.elapsed_secs_f64(),
                    ..default()
                },
                Mesh3d(palette.part.clone()),
                MeshMaterial3d(palette.airborne.clone()),
                RigidBody::Dynamic,
                Collider::cuboid(HALF, HALF, HALF),
                StickSlipFriction(Some(ep_material())),
                Velocity::zero(),
                // Point-mass-like, as the feeder's reference: a free box rocks on the
                // compliant contact and can walk down a slope.
                LockedAxes::ROTATION_LOCKED,
                Transform::from_translation(on_lane(lane, along, HALF)).with_rotation(rotation),
            ));
        }
    }
}

/// Moves the feeder trough along its throw direction, u(t) = A sin(ωt) (cos β, sin β), to
/// where it must be at the end of this fixed step (`Time<Fixed>`'s elapsed time).
fn drive_feeder(time: Res<Time>, mut troughs: Query<(&FeederTrough, &mut Transform)>) {
    let (a, f, beta) = FEEDER;
    let u = a * (std::f64::consts::TAU * f as f64 * time.elapsed_secs_f64()).sin() as f32;
    for (trough, mut transform) in &mut troughs {
        let offset = if trough.on {
            u * Vec3::new(beta.cos(), beta.sin(), 0.0)
        } else {
            Vec3::ZERO
        };
        transform.translation = trough.rest + offset;
    }
}

/// After every step: each part's position along its lane, once its start-up transient is
/// over, at the lane's sampling steps.
fn measure(time: Res<Time>, mut parts: Query<(&Part, &Transform, &mut Run)>) {
    let t = time.elapsed_secs_f64();
    let step = (t * PHYSICS_HZ).round() as u64;
    for (part, transform, mut run) in &mut parts {
        if t - run.started < SETTLE[part.0] || !step.is_multiple_of(SAMPLE_STEPS[part.0]) {
            continue;
        }
        let (dir, _, centre) = lane_frame(part.0);
        let sample = (t, (transform.translation - centre).dot(dir));
        if run.first.is_none() {
            run.first = Some(sample);
        }
        run.last = Some(sample);
    }
}

/// A part past the end of its lane starts over at the top, at rest, with a new run.
fn restart_parts(
    time: Res<Time>,
    mut parts: Query<(&Part, &mut Transform, &mut Velocity, &mut Run)>,
) {
    for (part, mut transform, mut velocity, mut run) in &mut parts {
        let (dir, rotation, centre) = lane_frame(part.0);
        if (transform.translation - centre).dot(dir) > END {
            *transform = Transform::from_translation(on_lane(part.0, START, HALF + 0.005))
                .with_rotation(rotation);
            *velocity = Velocity::zero();
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
    mut feeder: Query<&mut FeederTrough>,
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
        for mut trough in &mut feeder {
            trough.on = !trough.on;
        }
        // Lanes 2 and 3 start new runs: the old ones measured the other regime.
        for (_, part, mut run) in &mut parts {
            if part.0 > 0 {
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

/// Counts each part's regime (the most slippery of its contacts) after every step.
fn tally_regimes(contacts: Res<StickSlipContacts>, mut parts: Query<(Entity, &mut RegimeTally)>) {
    for (e, mut tally) in &mut parts {
        let i = match contacts.regime_of(e) {
            Some(Regime::Sticking) => 0,
            Some(Regime::StickSlip) => 1,
            Some(Regime::Sliding) => 2,
            None => 3,
        };
        tally.0[i] += 1;
    }
}

/// A part's colour: the regime of most steps since the last frame; white in flight.
fn colour_parts(
    palette: Res<Palette>,
    mut parts: Query<(&mut RegimeTally, &mut MeshMaterial3d<StandardMaterial>)>,
) {
    for (mut tally, mut material) in &mut parts {
        if tally.0 == [0; 4] {
            continue; // no step since the last frame (paused)
        }
        let most = (0..4).max_by_key(|i| (tally.0[*i], *i)).unwrap_or(3);
        tally.0 = [0; 4];
        let handle = match most {
            0..=2 => &palette.regimes[most],
            _ => &palette.airborne,
        };
        if material.0 != *handle {
            material.0 = handle.clone();
        }
    }
}

fn hud(
    stickslip: Res<StickSlipRapier>,
    time: Res<Time<Virtual>>,
    theory: Res<Theory>,
    parts: Query<(&Part, &Run)>,
    popov_base: Query<Has<StickSlipVibration>, With<PopovBase>>,
    mut text: Query<&mut Text, With<Hud>>,
) {
    let Ok(mut text) = text.single_mut() else {
        return;
    };
    let on = popov_base.iter().any(|on| on);
    let totals = stickslip.modifier().totals().unwrap_or_default();
    let state = match (time.is_paused(), time.relative_speed() < 1.0) {
        (true, _) => "   [paused]",
        (false, true) => "   [slow motion x0.1]",
        _ => "",
    };
    let measured = |lane: usize| {
        lane_speed(&parts, lane).map_or_else(
            || format!("settling ({} s)", SETTLE[lane]),
            |(v, n)| format!("{v:+.3} m/s ({n})"),
        )
    };
    let (popov, feeder) = if on {
        (
            format!("{:.3} m/s  Popov: mu0 (1 - a Psi(b*)) = tan", theory.popov),
            format!("{:.3} m/s  point-mass reference", theory.feeder),
        )
    } else {
        (
            "0          (vibration off)".into(),
            "0          (vibration off)".into(),
        )
    };
    text.0 = format!(
        "stickslip: vibrating conveyor    t = {t:.2} s    vibration {vib}{state}\n\
         \n\
         transport speed         measured (parts)    theory\n\
         1  no vibration         {s0:<19} 0          (EP holds: no creep)\n\
         2  Popov vibration      {s1:<19} {popov}\n\
         3  vibratory feeder     {s2:<19} {feeder}\n\
         \n\
         contacts  {st} sticking, {ss} stick-slip, {sl} sliding;  friction dissipates {pw:.2} mW\n\
         parts     green sticking, orange stick-slip, red sliding, white in flight\n\
         keys      V vibration  Space pause  S slow motion  R reset  G gizmos",
        t = stickslip.modifier().time(),
        vib = if on { "ON" } else { "OFF" },
        s0 = measured(0),
        s1 = measured(1),
        s2 = measured(2),
        st = totals.sticking,
        ss = totals.stick_slip,
        sl = totals.sliding,
        pw = 1e3 * totals.dissipated_power,
    );
}

/// Keeps each lane's label beside the lane's lower (front) end on screen.
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
