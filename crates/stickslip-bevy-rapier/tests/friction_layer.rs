//! stickslip's friction layer on bevy_rapier entities: a normal vibration source on the
//! ground (averaged, α = 0.6) lowers static friction to μ_ba (1 − α) = 0.2 (Popov's Eq. 4), so
//! a box that holds on a slope of tan θ = 0.3 without it slides with it; a ground with a
//! `SurfaceVelocity` of 0.5 m/s (a belt) carries a box at 0.5 m/s; with contact read-back on,
//! `StickSlipContacts` names the touching entities and reads the box's weight as its normal
//! force (within 1 %); a box that breaks away announces its contact and then its slide as
//! `RegimeChanged` messages, without flicker.

mod common;

use bevy::prelude::*;
use common::bevy_rapier::prelude::*;
use common::stickslip_bevy_rapier::{
    StickSlipContacts, StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin,
    StickSlipVibration, SurfaceVelocity,
};
use common::stickslip_rapier::{
    Amplitude, ReadBack, VibrationDirection, VibrationMode, VibrationSource,
};
use common::*;
use stickslip_core::waveform::Waveform;

const DT: f32 = 1.0 / 60.0;

/// A bevy_rapier app with stickslip (default material: EP μ 0.5, c 1e5), gravity tilted to
/// `tan`, a ground carrying `ground` and a 8 kg box on it.
fn app(tan: f64, ground: impl Bundle) -> (App, Entity, Entity) {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed {
            dt: DT,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::default());
    app.update();
    let th = tan.atan();
    let g = vect((9.81 * th.sin()) as f32, -(9.81 * th.cos()) as f32, 0.0);
    let mut q = app.world_mut().query::<&mut RapierConfiguration>();
    for mut c in q.iter_mut(app.world_mut()) {
        c.gravity = g;
    }
    let g = app
        .world_mut()
        .spawn((
            RigidBody::Fixed,
            cuboid(50.0, 0.1, 5.0),
            Transform::from_xyz(0.0, -0.1, 0.0),
            StickSlipFriction(None),
            ground,
        ))
        .id();
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid(0.1, 0.1, 0.1),
            ColliderMassProperties::Mass(8.0),
            LockedAxes::ROTATION_LOCKED,
            Velocity::zero(),
            Transform::from_xyz(0.0, 0.1, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    (app, g, b)
}

fn run(app: &mut App, n: usize) {
    for _ in 0..n {
        app.update();
    }
}

fn x(app: &App, e: Entity) -> f32 {
    app.world().get::<Transform>(e).unwrap().translation.x
}

#[test]
fn a_normal_vibration_lowers_static_friction() {
    let shaker = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.6),
        20_000.0,
        Waveform::Sine,
        0.0,
        VibrationMode::Averaged,
    )
    .unwrap();
    let (mut still, _, b_still) = app(0.3, ());
    let (mut shaken, _, b_shaken) = app(0.3, StickSlipVibration(shaker));
    run(&mut still, 5);
    run(&mut shaken, 5);
    let (x0_still, x0_shaken) = (x(&still, b_still), x(&shaken, b_shaken));
    run(&mut still, 60);
    run(&mut shaken, 60);
    let held = (x(&still, b_still) - x0_still).abs();
    let slid = x(&shaken, b_shaken) - x0_shaken;
    // g_ba = μ_ba/c = 5 µm: holding stays inside it; sliding (at Popov's reduced sliding
    // friction, which rises back towards μ_ba with the speed) goes thousands of times further.
    assert!(held < 5e-6, "without vibration the box moved {held} m");
    assert!(slid > 0.01, "with vibration the box moved only {slid} m");
}

#[test]
fn a_surface_velocity_carries_the_box() {
    let (mut app, _, b) = app(0.0, SurfaceVelocity(Vec3::new(0.5, 0.0, 0.0)));
    run(&mut app, 120);
    let v = app.world().get::<Velocity>(b).unwrap().linear;
    // Across the belt (3D: z; 2D: none).
    let across = (v - vect(v.x, v.y, 0.0)).length();
    assert!(
        (v.x - 0.5).abs() < 0.005 && across < 1e-3,
        "box velocity {v:?}"
    );
}

#[test]
fn contacts_are_read_back_as_entities() {
    let (mut app, ground, b) = app(0.0, ());
    app.world_mut()
        .resource_mut::<StickSlipRapier>()
        .modifier_mut()
        .set_read_back(ReadBack::Contacts);
    run(&mut app, 30);
    let contacts = &app.world().resource::<StickSlipContacts>().0;
    assert_eq!(contacts.len(), 1);
    let c = contacts[0];
    let pair = [c.collider1, c.collider2];
    assert!(pair.contains(&ground) && pair.contains(&b), "{pair:?}");
    let weight = 8.0 * 9.81;
    assert!(
        (c.normal_force - weight).abs() < 0.01 * weight,
        "normal force {} vs {weight}",
        c.normal_force
    );
}

#[derive(Resource, Default)]
struct Changes(Vec<common::stickslip_bevy_rapier::RegimeChanged>);

fn record(
    mut events: MessageReader<common::stickslip_bevy_rapier::RegimeChanged>,
    mut changes: ResMut<Changes>,
) {
    changes.0.extend(events.read().copied());
}

#[test]
fn regime_changes_arrive_as_messages() {
    use stickslip_core::law::Regime;
    // Tilted above break-away (tan θ 0.6 > μ_ba 0.5): the box sticks, breaks away, slides.
    let (mut app, ground, b) = app(0.6, ());
    app.init_resource::<Changes>().add_systems(Update, record);
    app.world_mut()
        .resource_mut::<StickSlipRapier>()
        .modifier_mut()
        .set_read_back(ReadBack::Contacts);
    run(&mut app, 90);
    let changes = &app.world().resource::<Changes>().0;
    let first = changes.first().expect("no regime message");
    assert_eq!(
        first.from, None,
        "the first message announces a new contact"
    );
    assert!([first.collider1, first.collider2].contains(&ground));
    assert!([first.collider1, first.collider2].contains(&b));
    assert_eq!(changes.last().unwrap().to, Regime::Sliding, "{changes:?}");
    // A steady slide does not flicker: new contact, (stick-slip,) sliding.
    assert!(changes.len() <= 3, "{changes:?}");
    // The slide dissipates what its friction does against the slip: P = |F_f| |ġ|.
    let contacts = &app.world().resource::<StickSlipContacts>().0;
    let c = contacts
        .iter()
        .find(|c| c.collider1 == b || c.collider2 == b)
        .expect("the box's contact");
    let f = Vec3::from(c.friction_force).length() as f64;
    let v = Vec3::from(c.slip_velocity).length() as f64;
    assert!(
        v > 0.1 && (c.dissipated_power - f * v).abs() < 0.01 * f * v,
        "{c:?}"
    );
}
