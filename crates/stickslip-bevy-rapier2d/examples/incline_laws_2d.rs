//! Three friction laws side by side in a 2D bevy_rapier app, in a real window: three inclines
//! of slope tan θ = 0.45, one box on each, the same start.
//!
//! 1. **bevy_rapier's own friction**, one coefficient 0.4 (Coulomb): the box slides down at
//!    a = g (sin θ − 0.4 cos θ) = 0.447 m/s².
//! 2. **stickslip's elasto-plastic law**, break-away 0.5 and sliding 0.4 (c = 1e4 1/m): the box
//!    holds, without creep (at most the elastic range μ_ba/c = 50 µm).
//! 3. **The law in the seed's sharp limit** (break-away and sliding μ0 = 0.5, c = 1e4 1/m)
//!    **under Popov's normal vibration** of the incline (α = 0.5, 2 kHz, averaged): static
//!    friction drops to μ0 (1 − α) = 0.25 < 0.45 and the box flows, at the speed where the mean
//!    sliding friction μ0 (1 − α Ψ(β)) equals the slope (Eq. 33).
//!
//! The HUD gives each lane's measurement beside its closed form. Boxes are coloured by the
//! regime of their contacts (green sticking, orange stick-slip, red sliding, white in flight,
//! grey: the engine's own friction); the contact gizmos show friction (arrow) and normal
//! (white). A box that reaches the end of its incline starts over. Keys: Space pause, S slow
//! motion, R reset.
//!
//! ```sh
//! cargo run --release -p stickslip-bevy-rapier2d --features window --example incline_laws_2d
//! # No display: under Xvfb (software Vulkan), 90 frames of 1/30 s, saved, then exit.
//! xvfb-run -a -s "-screen 0 1280x720x24" cargo run -p stickslip-bevy-rapier2d \
//!     --features window --example incline_laws_2d -- --screenshot incline.png --frames 90
//! ```

use bevy::camera::ScalingMode;
use bevy::prelude::*;
use bevy_rapier2d::prelude::*;
use stickslip_bevy_rapier2d::debug::{StickSlipDebugPlugin, regime_color};
use stickslip_bevy_rapier2d::window::{Hud, WindowedApp, command_line, hud_box, time_keys};
use stickslip_bevy_rapier2d::{
    FrictionMaterial, StickSlipContacts, StickSlipFriction, StickSlipRapierPlugin,
    StickSlipVibration,
};
use stickslip_core::contact::{Amplitude, VibrationDirection, VibrationMode, VibrationSource};
use stickslip_core::law::Law;
use stickslip_core::popov;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;

/// Slope tan θ.
const SLOPE: f32 = 0.45;
/// bevy_rapier's coefficient (lane 1) and the law's sliding coefficient (lanes 2, 3).
const MU_K: f64 = 0.4;
/// The law's break-away coefficient and stiffness (1/m).
const MU_BA: f64 = 0.5;
const C: f64 = 1e4;
/// Popov's normal vibration of lane 3: amplitude ratio α, frequency (Hz).
const ALPHA: f64 = 0.5;
const FREQUENCY: f64 = 2_000.0;
/// Physics rate (Hz).
const PHYSICS_HZ: f64 = 240.0;
/// Gravity (m/s²).
const G: f32 = 9.81;
/// The inclines' heights (m), length (m) and the boxes' half size (m).
const LANES: [f32; 3] = [1.2, -0.9, -3.0];
const LENGTH: f32 = 8.0;
const HALF: f32 = 0.15;
/// Where a box starts and restarts along its incline (m from the incline's centre).
const START: f32 = -3.5;
const END: f32 = 3.6;
/// Start-up before a box's measurement counts (s): lane 2's contact forms, lane 3's box
/// approaches Popov's speed as exp(−t/τ), τ ≈ 0.15 s.
const SETTLE: f32 = 0.5;

fn main() -> AppExit {
    let Some((shot, _)) = command_line("incline_laws_2d [--screenshot PATH] [--frames N]", 90, 0)
    else {
        return AppExit::error();
    };
    let mut app = App::new();
    app.add_plugins(WindowedApp::new(
        "stickslip: three friction laws on an incline (2D)",
    ))
    .insert_resource(TimestepMode::Fixed {
        dt: (1.0 / PHYSICS_HZ) as f32,
        substeps: 1,
    })
    .add_plugins(RapierPhysicsPlugin::<NoUserData>::default().in_fixed_schedule())
    .add_plugins(StickSlipRapierPlugin::default().in_fixed_schedule())
    .add_plugins(StickSlipDebugPlugin)
    .insert_resource(Time::<Fixed>::from_hz(PHYSICS_HZ))
    .add_systems(Startup, setup)
    .add_systems(FixedUpdate, restart)
    .add_systems(Update, (time_keys, reset_key, colour, hud));
    if let Some(shot) = shot {
        app.add_plugins(shot);
    }
    app.run()
}

/// A box on lane 0, 1 or 2, when it (re)started (s of simulated time), and where it was along
/// its incline once settled.
#[derive(Component)]
struct Part {
    lane: usize,
    started: f32,
    settled: Option<f32>,
}

/// The incline's frame: its centre, its downhill direction and its outward normal.
fn frame(lane: usize) -> (Vec2, Vec2, Vec2) {
    let theta = SLOPE.atan();
    let down = Vec2::new(theta.cos(), -theta.sin());
    let normal = Vec2::new(theta.sin(), theta.cos());
    (Vec2::new(0.0, LANES[lane]), down, normal)
}

/// Where a box rests at `s` along its incline.
fn on_incline(lane: usize, s: f32) -> Vec2 {
    let (centre, down, normal) = frame(lane);
    centre + down * s + normal * (0.05 + HALF + 1e-3)
}

/// The elasto-plastic law, break-away `MU_BA` and sliding `mu_k`.
fn elasto_plastic(mu_k: f64) -> FrictionMaterial {
    let law = Curve::constant(mu_k)
        .and_then(|c| Law::elasto_plastic(C, MU_BA, MU_BA, c))
        .expect("valid law");
    FrictionMaterial::new(law)
}

/// Popov's speed of lane 3: μ0 (1 − α Ψ(β*)) = tan θ, β* = c v*/(μ0 α f).
fn popov_speed() -> f64 {
    let target = (1.0 - SLOPE as f64 / MU_BA) / ALPHA;
    let beta = popov::beta_at_psi(&Waveform::Sine, target).unwrap_or(f64::NAN);
    beta * MU_BA * ALPHA * FREQUENCY / C
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut config: Query<&mut RapierConfiguration>,
) {
    for mut c in &mut config {
        c.gravity = Vec2::new(0.0, -G);
    }
    // A side view: an orthographic camera on the x-y plane.
    commands.spawn((
        Camera3d::default(),
        Projection::from(OrthographicProjection {
            scaling_mode: ScalingMode::FixedVertical {
                viewport_height: 9.0,
            },
            ..OrthographicProjection::default_3d()
        }),
        Transform::from_xyz(0.3, -0.4, 20.0).looking_at(Vec3::new(0.3, -0.4, 0.0), Vec3::Y),
    ));
    let unlit = |color: Color| StandardMaterial {
        base_color: color,
        unlit: true,
        ..default()
    };
    let slab = meshes.add(Cuboid::new(LENGTH, 0.1, 0.2));
    let slab_material = materials.add(unlit(Color::srgb(0.45, 0.47, 0.52)));
    let vibrating_material = materials.add(unlit(Color::srgb(0.35, 0.5, 0.7)));
    let part_mesh = meshes.add(Cuboid::new(2.0 * HALF, 2.0 * HALF, 0.3));
    let theta = SLOPE.atan();
    let source = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(ALPHA),
        FREQUENCY,
        Waveform::Sine,
        0.0,
        VibrationMode::Averaged,
    )
    .expect("valid source");
    for lane in 0..3 {
        let (centre, _, _) = frame(lane);
        let mut incline = commands.spawn((
            RigidBody::Fixed,
            Collider::cuboid(LENGTH / 2.0, 0.05),
            Transform::from_translation(centre.extend(0.0))
                .with_rotation(Quat::from_rotation_z(-theta)),
            Mesh3d(slab.clone()),
            MeshMaterial3d(slab_material.clone()),
        ));
        match lane {
            0 => {
                incline.insert(Friction::coefficient(MU_K as f32));
            }
            1 => {
                incline.insert(StickSlipFriction(Some(elasto_plastic(MU_K))));
            }
            _ => {
                incline.insert((
                    StickSlipFriction(Some(elasto_plastic(MU_BA))),
                    StickSlipVibration(source.clone()),
                    MeshMaterial3d(vibrating_material.clone()),
                ));
            }
        }
        let mut part = commands.spawn((
            Part {
                lane,
                started: 0.0,
                settled: None,
            },
            RigidBody::Dynamic,
            Collider::cuboid(HALF, HALF),
            ColliderMassProperties::Mass(1.0),
            LockedAxes::ROTATION_LOCKED,
            Velocity::zero(),
            Sleeping::disabled(),
            Transform::from_translation(on_incline(lane, START).extend(0.0))
                .with_rotation(Quat::from_rotation_z(-theta)),
            Mesh3d(part_mesh.clone()),
            MeshMaterial3d(materials.add(unlit(Color::srgb(0.6, 0.6, 0.6)))),
        ));
        match lane {
            0 => part.insert(Friction::coefficient(MU_K as f32)),
            1 => part.insert(StickSlipFriction(Some(elasto_plastic(MU_K)))),
            _ => part.insert(StickSlipFriction(Some(elasto_plastic(MU_BA)))),
        };
    }
    commands.spawn(hud_box());
}

/// Where a box is along its incline (m from the incline's centre).
fn along(lane: usize, at: Vec3) -> f32 {
    let (centre, down, _) = frame(lane);
    (at.truncate() - centre).dot(down)
}

/// Puts a box back at the start.
fn put_back(part: &mut Part, transform: &mut Transform, velocity: &mut Velocity, now: f32) {
    transform.translation = on_incline(part.lane, START).extend(0.0);
    *velocity = Velocity::zero();
    part.started = now;
    part.settled = None;
}

/// Boxes at the end of their incline start over; a box's settled position is kept.
fn restart(time: Res<Time>, mut parts: Query<(&mut Part, &mut Transform, &mut Velocity)>) {
    let now = time.elapsed_secs();
    for (mut part, mut transform, mut velocity) in &mut parts {
        let s = along(part.lane, transform.translation);
        if s > END {
            put_back(&mut part, &mut transform, &mut velocity, now);
        } else if part.settled.is_none() && now - part.started >= SETTLE {
            part.settled = Some(s);
        }
    }
}

/// R puts every box back at the start.
fn reset_key(
    keys: Res<ButtonInput<KeyCode>>,
    time: Res<Time<Fixed>>,
    mut parts: Query<(&mut Part, &mut Transform, &mut Velocity)>,
) {
    if keys.just_pressed(KeyCode::KeyR) {
        for (mut part, mut transform, mut velocity) in &mut parts {
            put_back(
                &mut part,
                &mut transform,
                &mut velocity,
                time.elapsed_secs(),
            );
        }
    }
}

/// Each box in the colour of its contacts' regime (lane 1: the engine's own, grey).
fn colour(
    contacts: Res<StickSlipContacts>,
    parts: Query<(Entity, &Part, &MeshMaterial3d<StandardMaterial>)>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    for (e, part, handle) in &parts {
        if part.lane == 0 {
            continue;
        }
        let color = contacts.regime_of(e).map_or(Color::WHITE, regime_color);
        if let Some(mut m) = materials.get_mut(&handle.0) {
            m.base_color = color;
        }
    }
}

/// Each lane's measurement beside its closed form.
fn hud(
    time: Res<Time<Fixed>>,
    parts: Query<(&Part, &Transform, &Velocity)>,
    mut text: Query<&mut Text, With<Hud>>,
) {
    let Ok(mut text) = text.single_mut() else {
        return;
    };
    let now = time.elapsed_secs();
    let theta = SLOPE.atan();
    // ASCII only: bevy's default font has no Greek letters.
    let mut lines = vec![format!(
        "slope tan(theta) = {SLOPE}, t = {now:.2} s (each box: 1 kg, from rest at the top)"
    )];
    let mut sorted: Vec<_> = parts.iter().collect();
    sorted.sort_by_key(|(p, ..)| p.lane);
    for (part, transform, velocity) in sorted {
        let (_, down, _) = frame(part.lane);
        let v = velocity.linear.dot(down);
        let t = now - part.started;
        let s = along(part.lane, transform.translation);
        lines.push(match part.lane {
            0 => {
                let a = G * (theta.sin() - MU_K as f32 * theta.cos());
                let measured = if t > 0.0 { v / t } else { 0.0 };
                format!(
                    "1. bevy_rapier's friction 0.4: slides at a = {measured:.3} m/s^2 \
                     (g (sin - 0.4 cos) = {a:.3})"
                )
            }
            1 => match part.settled {
                Some(s0) => format!(
                    "2. stickslip, break-away 0.5, sliding 0.4: holds, moved {:.2} um since \
                     {SETTLE} s (elastic range mu_ba/c = {:.0} um)",
                    (s - s0) * 1e6,
                    MU_BA / C * 1e6
                ),
                None => "2. stickslip, break-away 0.5, sliding 0.4: contact forming".into(),
            },
            _ => {
                let speed = match part.settled {
                    Some(_) => format!("{v:.3} m/s"),
                    None => "(settling)".into(),
                };
                format!(
                    "3. stickslip at 0.5, Popov's normal vibration (alpha {ALPHA}, 2 kHz): \
                     flows at {speed} (Eq. 33: {:.3} m/s)",
                    popov_speed()
                )
            }
        });
    }
    text.0 = lines.join("\n");
}
