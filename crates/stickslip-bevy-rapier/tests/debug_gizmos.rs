//! The contact gizmos (feature `debug`, headless: bevy's gizmo plugin without a renderer) in a
//! bevy_rapier app with stickslip: every stickslip contact is drawn in its regime's colour (a
//! resting box: sticking green; a pushed one: sliding red), nothing is drawn when the gizmo
//! group is disabled.

use bevy::asset::AssetPlugin;
use bevy::gizmos::{GizmoAsset, GizmoHandles, GizmoPlugin};
use bevy::mesh::skinning::SkinnedMeshInverseBindposes;
use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use std::any::TypeId;
use stickslip_bevy_rapier::debug::{StickSlipDebugPlugin, StickSlipGizmos, regime_color};
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapierPlugin};
use stickslip_core::law::Regime;

fn gizmo_app() -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed {
            dt: 1.0 / 60.0,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins((
            StickSlipRapierPlugin::default(),
            StickSlipDebugPlugin,
            AssetPlugin::default(),
            GizmoPlugin,
        ))
        // The gizmo plugin's skinned-mesh bounds read these (DefaultPlugins' mesh plugin adds them).
        .init_asset::<Mesh>()
        .init_asset::<SkinnedMeshInverseBindposes>();
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
    app.world_mut().spawn((
        RigidBody::Fixed,
        Collider::cuboid(20.0, 0.1, 5.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        StickSlipFriction(None),
    ));
    let mut part = |x: f32| {
        app.world_mut()
            .spawn((
                RigidBody::Dynamic,
                Collider::cuboid(0.1, 0.1, 0.1),
                ColliderMassProperties::Density(1000.0),
                LockedAxes::ROTATION_LOCKED,
                Transform::from_xyz(x, 0.1, 0.0),
                StickSlipFriction(None),
            ))
            .id()
    };
    let a = part(0.0);
    part(1.0);
    steps(&mut app, 30);
    let colors = drawn(&app);
    assert!(has(&colors, Regime::Sticking), "{} vertices", colors.len());
    assert!(!has(&colors, Regime::Sliding));

    // 8 kg at μ 0.5 breaks away above 39 N: push with 60 N.
    app.world_mut()
        .entity_mut(a)
        .insert(ExternalForce::at_point(
            Vec3::new(60.0, 0.0, 0.0),
            Vec3::new(0.0, 0.1, 0.0),
            Vec3::new(0.0, 0.1, 0.0),
        ));
    steps(&mut app, 30);
    let colors = drawn(&app);
    assert!(has(&colors, Regime::Sliding) && has(&colors, Regime::Sticking));

    app.world_mut()
        .resource_mut::<GizmoConfigStore>()
        .config_mut::<StickSlipGizmos>()
        .0
        .enabled = false;
    steps(&mut app, 1);
    assert!(drawn(&app).is_empty());
}
