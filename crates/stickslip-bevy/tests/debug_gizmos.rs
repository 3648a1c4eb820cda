//! The debug plugin draws what the contacts are (feature `debug`, headless: bevy's gizmo
//! plugin without a renderer). Invariants: with bevy's `GizmoPlugin` every stickslip contact
//! is drawn in its regime's colour (a resting box: sticking green, a pushed one: sliding red),
//! nothing is drawn when the gizmo group is disabled, and without `GizmoPlugin` the plugin
//! group still runs (the debug plugin stays off).

mod common;
use bevy::asset::AssetPlugin;
use bevy::gizmos::{GizmoAsset, GizmoHandles, GizmoPlugin};
use bevy::mesh::skinning::SkinnedMeshInverseBindposes;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use common::*;
use std::any::TypeId;
use stickslip_bevy::debug::{StickSlipGizmos, regime_color};
use stickslip_bevy::prelude::*;

fn gizmo_app() -> App {
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        StickSlipPlugins::default(), // before the gizmo plugin: the order does not matter
        AssetPlugin::default(),
        GizmoPlugin,
    ))
    .insert_resource(Time::<Fixed>::from_hz(HZ))
    .insert_resource(TimeUpdateStrategy::FixedTimesteps(1))
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
    let c = regime_color(regime).to_linear();
    colors.contains(&c)
}

#[test]
fn contacts_are_drawn_in_their_regimes_colour() {
    let mut app = gizmo_app();
    ground(&mut app, ep(1e5, 0.5, 0.4));
    let a = part(&mut app, 0.0);
    part(&mut app, 1.0);
    steps(&mut app, 30);
    let colors = drawn(&app);
    assert!(has(&colors, Regime::Sticking), "{} vertices", colors.len());
    assert!(!has(&colors, Regime::Sliding));

    app.world_mut().entity_mut(a).insert(ExternalForce {
        force: Vec3::new(60.0, 0.0, 0.0),
        torque: Vec3::ZERO,
    });
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

#[test]
fn without_gizmo_plugin_the_group_still_runs() {
    let mut app = app();
    app.finish();
    ground(&mut app, ep(1e5, 0.5, 0.4));
    part(&mut app, 0.0);
    steps(&mut app, 10);
    assert_eq!(app.world().resource::<ContactReports>().contacts.len(), 1);
    assert!(!app.world().contains_resource::<GizmoConfigStore>());
}
