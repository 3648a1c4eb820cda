//! The contact gizmos (feature `debug`, headless: bevy's gizmo plugin without a renderer) in
//! an avian app with stickslip, and `RegimeChanged`: every stickslip contact is drawn in its
//! regime's colour (a resting box: sticking green; a pushed one, over break-away: sliding
//! red; the messages say it left sticking and ended sliding), nothing is drawn when the gizmo group is disabled.

use avian3d::prelude::*;
use bevy::asset::AssetPlugin;
use bevy::gizmos::{GizmoAsset, GizmoHandles, GizmoPlugin};
use bevy::mesh::skinning::SkinnedMeshInverseBindposes;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use std::any::TypeId;
use std::time::Duration;
use stickslip_avian::debug::{StickSlipDebugPlugin, StickSlipGizmos, regime_color};
use stickslip_avian::{RegimeChanged, StickSlipAvianPlugin};
use stickslip_core::law::Regime;

/// Every `RegimeChanged` seen.
#[derive(Resource, Default)]
struct Seen(Vec<RegimeChanged>);

fn record(mut messages: MessageReader<RegimeChanged>, mut seen: ResMut<Seen>) {
    seen.0.extend(messages.read().copied());
}

fn gizmo_app() -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin, PhysicsPlugins::default()))
        .insert_resource(Time::<Fixed>::from_hz(60.0))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 60.0,
        )))
        .add_plugins((
            StickSlipAvianPlugin::default(),
            StickSlipDebugPlugin,
            AssetPlugin::default(),
            GizmoPlugin,
        ))
        .init_asset::<Mesh>()
        .init_asset::<SkinnedMeshInverseBindposes>()
        .init_resource::<Seen>()
        .add_systems(PostUpdate, record);
    app.finish();
    app.cleanup();
    app.update();
    app
}

/// The colours of the line vertices drawn for `StickSlipGizmos` in the last frame.
fn drawn(app: &App) -> Vec<LinearRgba> {
    let handles = app.world().resource::<GizmoHandles>();
    let Some(Some(h)) = handles.handles().get(&TypeId::of::<StickSlipGizmos>()) else {
        return Vec::new();
    };
    let assets = app.world().resource::<Assets<GizmoAsset>>();
    let buffer = assets.get(h).unwrap().buffer().buffer();
    buffer
        .list_colors
        .iter()
        .chain(buffer.strip_colors.iter())
        .copied()
        .collect()
}

fn has(colors: &[LinearRgba], regime: Regime) -> bool {
    colors.contains(&regime_color(regime).to_linear())
}

fn steps(app: &mut App, n: usize) {
    for _ in 0..n {
        app.update();
    }
}

#[test]
fn contacts_are_drawn_in_their_regimes_colour() {
    let mut app = gizmo_app();
    let friction = Friction::new(0.4).with_static_coefficient(0.6);
    app.world_mut().spawn((
        RigidBody::Static,
        Collider::cuboid(40.0, 0.2, 10.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        friction,
    ));
    let mut part = |x: f32| {
        app.world_mut()
            .spawn((
                RigidBody::Dynamic,
                Collider::cuboid(0.2, 0.2, 0.2),
                Mass(8.0),
                LockedAxes::ROTATION_LOCKED,
                Transform::from_xyz(x, 0.1, 0.0),
                SleepingDisabled,
                friction,
            ))
            .id()
    };
    let a = part(0.0);
    part(1.0);
    steps(&mut app, 30);
    let colors = drawn(&app);
    assert!(has(&colors, Regime::Sticking), "{} vertices", colors.len());
    assert!(!has(&colors, Regime::Sliding));
    let seen = &app.world().resource::<Seen>().0;
    assert!(seen.iter().any(|m| (m.collider1 == a || m.collider2 == a)
        && m.from.is_none()
        && m.to == Regime::Sticking));
    app.world_mut().resource_mut::<Seen>().0.clear();

    // 8 kg at μ_s 0.6 breaks away above 47 N: push with 60 N.
    app.world_mut()
        .entity_mut(a)
        .insert(ConstantForce(Vec3::new(60.0, 0.0, 0.0)));
    steps(&mut app, 30);
    let colors = drawn(&app);
    assert!(has(&colors, Regime::Sliding) && has(&colors, Regime::Sticking));
    let seen = &app.world().resource::<Seen>().0;
    // It leaves sticking (through stick-slip, as the law breaks away) and ends sliding.
    let of_a: Vec<_> = seen
        .iter()
        .filter(|m| m.collider1 == a || m.collider2 == a)
        .collect();
    assert!(
        of_a.first()
            .is_some_and(|m| m.from == Some(Regime::Sticking))
            && of_a.last().is_some_and(|m| m.to == Regime::Sliding),
        "the box's regime changes: {of_a:?}"
    );

    app.world_mut()
        .resource_mut::<GizmoConfigStore>()
        .config_mut::<StickSlipGizmos>()
        .0
        .enabled = false;
    steps(&mut app, 1);
    assert!(drawn(&app).is_empty());
}
