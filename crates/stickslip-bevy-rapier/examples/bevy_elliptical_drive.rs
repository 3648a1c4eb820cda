//! Vibration that transports by itself, in a real window, as a bevy_rapier app with stickslip
//! added (`RapierPhysicsPlugin::<NoUserData>` + `StickSlipRapierPlugin`, in bevy's fixed
//! schedule at 240 Hz): two flat plates side by side, each
//! vibrating elliptically — a normal (α = 0.6) and a tangential (0.75 of the load, along x)
//! sine component at 2 kHz (averaged), the tangential one a quarter period after the normal
//! one on the far plate and a quarter period before it on the near one. No force pushes the
//! parts along the plates, yet they move: at Popov's compliant contact theory's free drive
//! velocity (`stickslip_core::popov::free_drive_velocity`), one plate forward, the other
//! backward. The HUD shows each plate's measured mean speed beside the theory's.
//! (`crates/stickslip-bevy-rapier/tests/drive.rs` checks the same headless.)
//!
//! Keys: F flip both ellipses (phase shift ↔ −phase shift), Space pause, S slow motion (×0.1),
//! R reset.
//!
//! ```sh
//! cargo run --release -p stickslip-bevy-rapier --features window --example bevy_elliptical_drive
//! xvfb-run -a -s "-screen 0 1280x720x24" cargo run -p stickslip-bevy-rapier --features window \
//!     --example bevy_elliptical_drive -- --screenshot drive.png --frames 90
//! ```

use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use stickslip_bevy_rapier::window::{Hud, WindowedApp, command_line, hud_box, time_keys};
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapierPlugin, StickSlipVibration};
use stickslip_core::law::Law;
use stickslip_core::popov::{CompliantContact, Oscillation, free_drive_velocity};
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;
use stickslip_rapier_035::{
    Amplitude, FrictionMaterial, VibrationComponent, VibrationDirection, VibrationMode,
    VibrationSource,
};

const MU0: f64 = 0.5;
const C: f64 = 1e4;
const ALPHA: f64 = 0.6;
const TANGENTIAL: f64 = 0.75;
const FREQUENCY: f64 = 2000.0;
/// Phase shift (periods) of the tangential component on each plate.
const SHIFTS: [f64; 2] = [0.25, -0.25];
/// Plate centres along z; parts start at x = 0 and wrap at ±LIMIT.
const PLATES: [f32; 2] = [-0.6, 0.6];
const LIMIT: f32 = 1.6;
const PARTS: usize = 4;
const HALF: f32 = 0.06;

/// The source of a plate and the theory's drive velocity along x (m/s).
fn source(shift: f64) -> (VibrationSource, f64) {
    let components = [
        VibrationComponent::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(ALPHA),
            Waveform::Sine,
            0.0,
        ),
        VibrationComponent::new(
            VibrationDirection::Tangential {
                axis: [1.0, 0.0, 0.0],
            },
            Amplitude::Ratio(TANGENTIAL),
            Waveform::Sine,
            shift,
        ),
    ]
    .into_iter()
    .collect::<Result<Vec<_>, _>>()
    .expect("valid components");
    let src = VibrationSource::superimposed(&components, FREQUENCY, VibrationMode::Averaged)
        .expect("valid source");
    (src.clone(), theory_velocity(&src).unwrap_or(f64::NAN))
}

/// Popov's compliant contact under the source: the law's sharp limit (μ_ba = μ_max = μ0) of
/// stiffness C is the contact k_x = C F̄, k_z = F̄ at ū_z = 1 (F̄ cancels; take 1), whose
/// in-plane amplitudes are slip lengths μ0/C. The plate drives the part's base by −A w, so the
/// part moves at minus the theory's free drive velocity.
fn theory_velocity(src: &VibrationSource) -> Result<f64, stickslip_core::ParamError> {
    let mut ex = src.excitation(MU0, 1.0)?;
    for o in [&mut ex.tangential, &mut ex.transverse]
        .into_iter()
        .flatten()
    {
        *o = Oscillation::new(o.amplitude() * MU0 / C, o.waveform().clone(), o.phase())?;
    }
    let contact = CompliantContact::new(C, 1.0, MU0, 1.0)?;
    Ok(-free_drive_velocity(&contact, &ex, FREQUENCY)?.unwrap_or(0.0))
}

#[derive(Component)]
struct Plate(usize);

#[derive(Component)]
struct Part {
    plate: usize,
    start: Vec3,
}

/// Sign of the phase shifts (F flips it) and the parts' mean speeds.
#[derive(Resource)]
struct Drive {
    flipped: bool,
    theory: [f64; 2],
    speed: [f32; 2],
}

fn main() -> AppExit {
    let Some((shot, _)) = command_line(
        "bevy_elliptical_drive [--screenshot PATH] [--frames N]",
        90,
        0,
    ) else {
        return AppExit::error();
    };
    let mut app = App::new();
    app.add_plugins(WindowedApp::new("stickslip: elliptical vibration drive"))
        // bevy_rapier in the fixed schedule, one rapier step per tick, stickslip bracketing it.
        .insert_resource(TimestepMode::Fixed {
            dt: 1.0 / 240.0,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default().in_fixed_schedule())
        .add_plugins(StickSlipRapierPlugin::default().in_fixed_schedule())
        .insert_resource(Time::<Fixed>::from_hz(240.0))
        .insert_resource(Drive {
            flipped: false,
            theory: [source(SHIFTS[0]).1, source(SHIFTS[1]).1],
            speed: [0.0; 2],
        })
        .add_systems(Startup, setup)
        .add_systems(FixedUpdate, (measure, wrap).after(PhysicsSet::Writeback))
        .add_systems(Update, (keys, time_keys, hud));
    if let Some(shot) = shot {
        // Reproducible pictures: the window at a given frame, every frame 1/30 s.
        app.add_plugins(shot);
    }
    app.run()
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    commands.spawn((
        Camera3d::default(),
        Transform::from_xyz(0.0, 2.2, 3.0).looking_at(Vec3::new(0.0, 0.0, 0.0), Vec3::Y),
    ));
    commands.spawn((
        DirectionalLight {
            illuminance: 8000.0,
            shadow_maps_enabled: true,
            ..default()
        },
        Transform::from_xyz(-2.0, 6.0, 3.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    let plate_mat = materials.add(Color::srgb(0.3, 0.5, 0.85));
    let part_mats = [
        materials.add(Color::srgb(0.95, 0.6, 0.2)),
        materials.add(Color::srgb(0.3, 0.8, 0.4)),
    ];
    let plate_mesh = meshes.add(Cuboid::new(2.0 * LIMIT + 0.4, 0.1, 0.5));
    let part_mesh = meshes.add(Cuboid::from_length(2.0 * HALF));
    let law = Law::elasto_plastic(C, MU0, MU0, Curve::constant(MU0).expect("positive"))
        .expect("valid law");
    for (i, &z) in PLATES.iter().enumerate() {
        commands.spawn((
            Plate(i),
            RigidBody::Fixed,
            Collider::cuboid(LIMIT + 0.2, 0.05, 0.25),
            StickSlipFriction(Some(FrictionMaterial::new(law.clone()))),
            StickSlipVibration(source(SHIFTS[i]).0),
            Mesh3d(plate_mesh.clone()),
            MeshMaterial3d(plate_mat.clone()),
            Transform::from_xyz(0.0, -0.05, z),
        ));
        for k in 0..PARTS {
            let start = Vec3::new(-0.45 + 0.3 * k as f32, HALF + 0.001, z);
            commands.spawn((
                Part { plate: i, start },
                RigidBody::Dynamic,
                Collider::cuboid(HALF, HALF, HALF),
                LockedAxes::ROTATION_LOCKED,
                Velocity::zero(),
                Mesh3d(part_mesh.clone()),
                MeshMaterial3d(part_mats[i].clone()),
                Transform::from_translation(start),
            ));
        }
    }
    commands.spawn(hud_box());
}

/// Mean speed of each plate's parts along x, low-pass filtered over 0.3 s.
fn measure(mut drive: ResMut<Drive>, parts: Query<(&Part, &Velocity)>, time: Res<Time>) {
    let w = (time.delta_secs() / 0.3).min(1.0);
    for plate in 0..2 {
        let (sum, n) = parts
            .iter()
            .filter(|(p, _)| p.plate == plate)
            .fold((0.0, 0), |(s, n), (_, v)| (s + v.linear.x, n + 1));
        let v = sum / n.max(1) as f32;
        drive.speed[plate] += w * (v - drive.speed[plate]);
    }
}

/// Parts leaving a plate come back at its other end.
fn wrap(mut parts: Query<(&Part, &mut Transform)>) {
    for (_, mut t) in &mut parts {
        if t.translation.x > LIMIT {
            t.translation.x -= 2.0 * LIMIT - 0.2;
        } else if t.translation.x < -LIMIT {
            t.translation.x += 2.0 * LIMIT - 0.2;
        }
    }
}

fn keys(
    input: Res<ButtonInput<KeyCode>>,
    mut drive: ResMut<Drive>,
    mut plates: Query<(&Plate, &mut StickSlipVibration)>,
    mut parts: Query<(&Part, &mut Transform, &mut Velocity)>,
) {
    if input.just_pressed(KeyCode::KeyF) {
        drive.flipped = !drive.flipped;
        let sign = if drive.flipped { -1.0 } else { 1.0 };
        for (p, mut vib) in &mut plates {
            let (src, v) = source(sign * SHIFTS[p.0]);
            vib.0 = src;
            drive.theory[p.0] = v;
        }
    }
    if input.just_pressed(KeyCode::KeyR) {
        for (p, mut t, mut v) in &mut parts {
            t.translation = p.start;
            *v = Velocity::zero();
        }
    }
}

fn hud(drive: Res<Drive>, time: Res<Time<Virtual>>, mut text: Query<&mut Text, With<Hud>>) {
    let Ok(mut text) = text.single_mut() else {
        return;
    };
    let sign = if drive.flipped { -1.0 } else { 1.0 };
    let mut s = format!(
        "elliptical vibration, no applied force   t = {:.1} s\n\
         normal alpha = {ALPHA}, tangential {TANGENTIAL} of the load along x, sine, \
         {FREQUENCY} Hz (averaged), mu0 = {MU0}\n",
        time.elapsed_secs_f64()
    );
    for (i, name) in ["far plate", "near plate"].iter().enumerate() {
        s += &format!(
            "{name}: phase shift {:+.2} periods   measured {:+.1} mm/s   theory {:+.1} mm/s\n",
            sign * SHIFTS[i],
            drive.speed[i] * 1e3,
            drive.theory[i] * 1e3
        );
    }
    s += "F flip the ellipses   Space pause   S slow motion   R reset";
    text.0 = s;
}
