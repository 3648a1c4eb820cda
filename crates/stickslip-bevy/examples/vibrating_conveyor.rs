//! Three lanes side by side, same parts, same start, in a real window:
//!
//! 1. an inclined trough (slope 0.3) with elasto-plastic friction (μ_ba = 0.5): the parts stay
//!    put, the law holds them without creep;
//! 2. the same trough with Popov's normal vibration of its base (α = 0.6, 20 kHz, averaged):
//!    static friction drops to 0.2 < 0.3, the parts flow, and the HUD shows their speed beside
//!    the theory's conveying speed (μ_k (1 − α Ψ(β)) = 0.3);
//! 3. a classic vibratory feeder: a horizontal trough vibrating 3 mm at 15 Hz along a 30 deg
//!    throw angle (throw number 1.36), so that the parts hop forward.
//!
//! Parts are coloured by the regime of their contacts (green sticking, orange stick-slip, red
//! sliding); contact gizmos show friction forces and normals. Keys: V vibration of lane 2 on
//! or off, Space pause, S slow motion, R reset, G gizmos.
//!
//! ```sh
//! cargo run --release -p stickslip-bevy --features window --example vibrating_conveyor
//! # no display: under Xvfb, save the window after 120 frames and exit
//! xvfb-run -a -s "-screen 0 1280x720x24" cargo run -p stickslip-bevy --features window \
//!     --example vibrating_conveyor -- --screenshot conveyor.png --frames 60
//! ```

use bevy::diagnostic::FrameCount;
use bevy::prelude::*;
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured, save_to_disk};
use stickslip_bevy::debug::{StickSlipGizmos, regime_color};
use stickslip_bevy::prelude::*;
use stickslip_core::law::{Law, Regime};
use stickslip_core::popov;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;

const SLOPE: f32 = 0.3;
const MU_BA: f64 = 0.5;
const MU_K: f64 = 0.52;
const C: f64 = 1e5;
const ALPHA: f64 = 0.6;
const F_VIB: f64 = 20_000.0;
/// Vibratory feeder: amplitude (m), frequency (Hz), throw angle (rad).
const FEEDER: (f32, f32, f32) = (0.003, 15.0, std::f32::consts::FRAC_PI_6);
/// Lane positions along z.
const LANES: [f32; 3] = [-1.2, 0.0, 1.2];

#[derive(Resource)]
struct Options {
    screenshot: Option<(String, u32)>,
}

#[derive(Component)]
struct Part(usize);

#[derive(Component)]
struct ShakerBase;

#[derive(Component)]
struct FeederTrough {
    base: Vec3,
}

#[derive(Component)]
struct Hud;

#[derive(Resource)]
struct Palette {
    idle: Handle<StandardMaterial>,
    regimes: [Handle<StandardMaterial>; 3],
    part_mesh: Handle<Mesh>,
}

fn main() -> AppExit {
    let mut screenshot = None;
    let args: Vec<String> = std::env::args().collect();
    let mut frames = 120u32;
    let mut path = None;
    let mut i = 1;
    while i < args.len() {
        match args[i].as_str() {
            "--screenshot" if i + 1 < args.len() => {
                path = Some(args[i + 1].clone());
                i += 1;
            }
            "--frames" if i + 1 < args.len() => {
                frames = match args[i + 1].parse() {
                    Ok(n) => n,
                    Err(_) => {
                        eprintln!("--frames needs a number, got {}", args[i + 1]);
                        return AppExit::error();
                    }
                };
                i += 1;
            }
            other => {
                eprintln!("unknown argument {other}; usage: [--screenshot PATH] [--frames N]");
                return AppExit::error();
            }
        }
        i += 1;
    }
    if let Some(p) = path {
        screenshot = Some((p, frames));
    }
    if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
        eprintln!("no display: run under a desktop or `xvfb-run -a` (see the example's header)");
        return AppExit::error();
    }
    App::new()
        .add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(Window {
                title: "stickslip: vibrating conveyor".into(),
                resolution: (1280, 720).into(),
                ..default()
            }),
            ..default()
        }))
        .add_plugins(StickSlipPlugins::default())
        .insert_resource(Time::<Fixed>::from_hz(600.0))
        .insert_resource(Options { screenshot })
        .add_systems(Startup, setup)
        .add_systems(
            FixedPostUpdate,
            drive_feeder.before(StickSlipSystems::Prepare),
        )
        .add_systems(Update, (keys, colour_parts, hud, shot_and_exit))
        .run()
}

fn ep_material() -> FrictionMaterial {
    let curve = Curve::constant(MU_K).expect("positive");
    FrictionMaterial::new(Law::elasto_plastic(C, MU_BA, MU_K, curve).expect("valid"))
}

fn vibration() -> Vibration {
    Vibration(
        VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(ALPHA),
            F_VIB,
            Waveform::Sine,
            0.0,
            VibrationMode::Averaged,
        )
        .expect("valid source"),
    )
}

/// The conveying speed of Popov's theory on lane 2: μ_k (1 − α Ψ(β)) = slope.
fn theory_speed() -> f64 {
    let target = (1.0 - SLOPE as f64 / MU_K) / ALPHA;
    let (mut lo, mut hi) = (1e-6, 100.0);
    // Ψ falls with β: bisection.
    for _ in 0..100 {
        let mid = (lo * hi as f64).sqrt();
        if popov::psi(&Waveform::Sine, mid).unwrap_or(0.0) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo * MU_K * ALPHA * F_VIB / C
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    commands.spawn((
        Camera3d::default(),
        Transform::from_xyz(-0.6, 2.2, 4.2).looking_at(Vec3::new(0.2, -0.2, 0.0), Vec3::Y),
    ));
    commands.spawn((
        DirectionalLight {
            shadow_maps_enabled: true,
            ..default()
        },
        Transform::from_xyz(2.0, 5.0, 3.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    let trough_mat = materials.add(Color::srgb(0.35, 0.38, 0.45));
    let shaker_mat = materials.add(Color::srgb(0.3, 0.45, 0.7));
    let palette = Palette {
        idle: materials.add(Color::srgb(0.7, 0.7, 0.7)),
        regimes: [
            materials.add(regime_color(Regime::Sticking)),
            materials.add(regime_color(Regime::StickSlip)),
            materials.add(regime_color(Regime::Sliding)),
        ],
        part_mesh: meshes.add(Cuboid::new(0.1, 0.1, 0.1)),
    };
    let base_mesh = meshes.add(Cuboid::new(3.0, 0.1, 0.6));
    let wall_mesh = meshes.add(Cuboid::new(3.0, 0.2, 0.04));
    let tilt = Quat::from_rotation_z(-SLOPE.atan());
    for (lane, z) in LANES.iter().enumerate() {
        let (rotation, center) = if lane < 2 {
            (tilt, Vec3::new(0.0, 0.0, *z))
        } else {
            (Quat::IDENTITY, Vec3::new(0.0, -0.5, *z))
        };
        let mut base = commands.spawn((
            Mesh3d(base_mesh.clone()),
            MeshMaterial3d(if lane == 1 {
                shaker_mat.clone()
            } else {
                trough_mat.clone()
            }),
            Collider::cuboid(1.5, 0.05, 0.3),
            FrictionLaw::new(ep_material()),
            Transform::from_translation(center).with_rotation(rotation),
        ));
        if lane == 2 {
            base.insert((
                RigidBody::KinematicPositionBased,
                FeederTrough { base: center },
            ));
        } else {
            base.insert(RigidBody::Fixed);
        }
        if lane == 1 {
            base.insert((vibration(), ShakerBase));
        }
        let trough = base.id();
        // Side walls and an end stop as children (plain rapier friction).
        for (offset, mesh, half) in [
            (
                Vec3::new(0.0, 0.1, 0.32),
                wall_mesh.clone(),
                Vec3::new(1.5, 0.1, 0.02),
            ),
            (
                Vec3::new(0.0, 0.1, -0.32),
                wall_mesh.clone(),
                Vec3::new(1.5, 0.1, 0.02),
            ),
        ] {
            commands.spawn((
                Mesh3d(mesh),
                MeshMaterial3d(trough_mat.clone()),
                Collider::cuboid(half.x, half.y, half.z),
                Friction(0.1),
                Transform::from_translation(offset),
                ChildOf(trough),
            ));
        }
        commands.spawn((
            Mesh3d(meshes.add(Cuboid::new(0.04, 0.2, 0.6))),
            MeshMaterial3d(trough_mat.clone()),
            Collider::cuboid(0.02, 0.1, 0.3),
            Friction(0.1),
            Transform::from_xyz(1.45, 0.1, 0.0),
            ChildOf(trough),
        ));
    }
    commands.insert_resource(palette);
    commands.run_system_cached(spawn_parts);
    commands.spawn((
        Hud,
        Text::new(""),
        TextFont {
            font_size: FontSize::Px(16.0),
            ..default()
        },
        Node {
            position_type: PositionType::Absolute,
            top: px(10),
            left: px(10),
            ..default()
        },
    ));
}

fn spawn_parts(mut commands: Commands, palette: Res<Palette>) {
    let tilt = Quat::from_rotation_z(-SLOPE.atan());
    for (lane, z) in LANES.iter().enumerate() {
        for k in 0..4 {
            let local_x = -1.2 + 0.3 * k as f32;
            let (rotation, pos) = if lane < 2 {
                (
                    tilt,
                    tilt * Vec3::new(local_x, 0.1, 0.0) + Vec3::new(0.0, 0.0, *z),
                )
            } else {
                (Quat::IDENTITY, Vec3::new(local_x, -0.5 + 0.1, *z))
            };
            commands.spawn((
                Part(lane),
                Mesh3d(palette.part_mesh.clone()),
                MeshMaterial3d(palette.idle.clone()),
                RigidBody::Dynamic,
                Collider::cuboid(0.05, 0.05, 0.05),
                Transform::from_translation(pos).with_rotation(rotation),
            ));
        }
    }
}

/// Moves the feeder trough along its throw direction, u(t) = A sin(ωt) (cos β, sin β).
fn drive_feeder(time: Res<Time>, mut troughs: Query<(&FeederTrough, &mut Transform)>) {
    let (a, f, beta) = FEEDER;
    // The pose the step moves to: the end of this fixed step.
    let t = time.elapsed_secs() + time.delta_secs();
    let u = a * (std::f32::consts::TAU * f * t).sin();
    for (trough, mut transform) in &mut troughs {
        transform.translation = trough.base + u * Vec3::new(beta.cos(), beta.sin(), 0.0);
    }
}

#[allow(clippy::too_many_arguments)]
fn keys(
    mut commands: Commands,
    keys: Res<ButtonInput<KeyCode>>,
    mut time: ResMut<Time<Virtual>>,
    mut gizmos: ResMut<GizmoConfigStore>,
    shaker: Query<(Entity, Has<Vibration>), With<ShakerBase>>,
    parts: Query<Entity, With<Part>>,
) {
    if keys.just_pressed(KeyCode::KeyV) {
        for (e, on) in &shaker {
            if on {
                commands.entity(e).remove::<Vibration>();
            } else {
                commands.entity(e).insert(vibration());
            }
        }
    }
    if keys.just_pressed(KeyCode::Space) {
        time.toggle();
    }
    if keys.just_pressed(KeyCode::KeyS) {
        let slow = time.relative_speed() < 1.0;
        time.set_relative_speed(if slow { 1.0 } else { 0.2 });
    }
    if keys.just_pressed(KeyCode::KeyG) {
        gizmos.config_mut::<StickSlipGizmos>().0.enabled ^= true;
    }
    if keys.just_pressed(KeyCode::KeyR) {
        for e in &parts {
            commands.entity(e).despawn();
        }
        commands.run_system_cached(spawn_parts);
    }
}

/// The worst regime of each part's contacts sets its colour.
fn colour_parts(
    contacts: Res<ContactReports>,
    palette: Res<Palette>,
    mut parts: Query<(Entity, &mut MeshMaterial3d<StandardMaterial>), With<Part>>,
) {
    for (e, mut material) in &mut parts {
        let worst = contacts
            .of(e)
            .map(|c| c.report.regime)
            .max_by_key(|r| match r {
                Regime::Sticking => 0,
                Regime::StickSlip => 1,
                Regime::Sliding => 2,
            });
        let handle = match worst {
            None => &palette.idle,
            Some(Regime::Sticking) => &palette.regimes[0],
            Some(Regime::StickSlip) => &palette.regimes[1],
            Some(Regime::Sliding) => &palette.regimes[2],
        };
        if material.0 != *handle {
            material.0 = handle.clone();
        }
    }
}

fn hud(
    contacts: Res<ContactReports>,
    time: Res<Time<Virtual>>,
    parts: Query<(&Part, &Velocity)>,
    shaker: Query<Has<Vibration>, With<ShakerBase>>,
    mut text: Query<&mut Text, With<Hud>>,
) {
    let mut speed = [0.0f32; 3];
    let mut count = [0usize; 3];
    for (part, v) in &parts {
        // Speed along each lane's downhill / forward direction.
        let along = if part.0 < 2 {
            Quat::from_rotation_z(-SLOPE.atan()) * Vec3::X
        } else {
            Vec3::X
        };
        speed[part.0] += v.linear.dot(along);
        count[part.0] += 1;
    }
    for (s, n) in speed.iter_mut().zip(count) {
        *s /= n.max(1) as f32;
    }
    let vib = shaker.iter().any(|on| on);
    let totals = &contacts.totals;
    let Ok(mut text) = text.single_mut() else {
        return;
    };
    text.0 = format!(
        "stickslip: friction that sticks, breaks away and changes when the surface vibrates\n\
         t = {:.2} s{}{}\n\
         lane 1  inclined trough, no vibration    mean speed {:+.4} m/s (EP holds: 0)\n\
         lane 2  same trough, Popov vibration {}  mean speed {:+.4} m/s (theory {:.4} m/s)\n\
         lane 3  vibratory feeder 3 mm, 15 Hz, throw 30 deg  mean speed {:+.4} m/s\n\
         contacts: {} sticking, {} stick-slip, {} sliding; dissipated {:.2} W\n\
         V vibration  Space pause  S slow motion  R reset  G gizmos",
        contacts.time,
        if time.is_paused() { "  [paused]" } else { "" },
        if time.relative_speed() < 1.0 {
            "  [slow motion]"
        } else {
            ""
        },
        speed[0],
        if vib { "ON " } else { "OFF" },
        speed[1],
        theory_speed(),
        speed[2],
        totals.sticking,
        totals.stick_slip,
        totals.sliding,
        totals.dissipated_power,
    );
}

/// Frame after which the app exits once the screenshot is taken.
#[derive(Resource, Default)]
struct ExitAt(Option<u32>);

/// `--screenshot PATH --frames N`: save the window at frame N and exit (CI and docs). The
/// PNG is written on an I/O task: exit a few frames later so that it is complete.
fn shot_and_exit(
    mut commands: Commands,
    frames: Res<FrameCount>,
    options: Res<Options>,
    exit_at: Option<Res<ExitAt>>,
    mut exit: MessageWriter<AppExit>,
) {
    let Some((path, n)) = &options.screenshot else {
        return;
    };
    if frames.0 == *n {
        let path = path.clone();
        commands.spawn(Screenshot::primary_window()).observe(
            move |captured: On<ScreenshotCaptured>,
                  frames: Res<FrameCount>,
                  mut commands: Commands| {
                save_to_disk(path.clone())(captured);
                commands.insert_resource(ExitAt(Some(frames.0 + 10)));
            },
        );
    }
    if let Some(at) = exit_at.and_then(|e| e.0)
        && frames.0 >= at
    {
        exit.write(AppExit::Success);
    }
    // A screenshot that never arrives must not hang a CI run.
    if frames.0 > *n + 600 {
        eprintln!("no screenshot after {} frames", frames.0);
        exit.write(AppExit::error());
    }
}
