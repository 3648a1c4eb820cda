//! Scenario files as bevy_rapier apps (feature `scenario`). Invariants: every shipped
//! scenario (`scenarios/*.toml`), spawned by `spawn_scenario` and stepped by bevy_rapier with
//! stickslip and its drivers, ends where the scenario crate's headless `Runner` (the same
//! rapier 0.35) ends after a second of simulated time (at most 2 000 steps): the same number
//! of steps of the same length, and every body within 10 µm + 0.1 % of its travel or two
//! steps of its motion (2·dt·|v|) — bevy_rapier builds its bodies and colliders in its own
//! order and way, which changes the solver's rounding by ulps (the test prints how many
//! bodies are bit-identical); the viewer's framing shows every moving body whole (all corners
//! of their bounding boxes project inside a 16:9 view with bevy's default field of view) and
//! not lost in the distance (the region spans at least a third of the view); reloading
//! replaces the entities and leaves no rapier object behind; an invalid scenario is a typed
//! error and spawns nothing.

use bevy::camera::CameraProjection;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_rapier3d::plugin::context::{RapierContextColliders, RapierRigidBodySet};
use bevy_rapier3d::prelude::*;
use std::path::PathBuf;
use std::time::Duration;
use stickslip_bevy_rapier::scenario::{
    LoadedScenario, Scenario, StickSlipScenarioPlugin, spawn_scenario,
};
use stickslip_bevy_rapier::{StickSlipRapier, StickSlipRapierPlugin};
use stickslip_scenario_035::Runner;

fn scenarios() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenarios");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("scenarios/")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 5, "the shipped scenarios: {files:?}");
    files
}

fn app() -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(
            16,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins((
            StickSlipRapierPlugin::default(),
            StickSlipScenarioPlugin::default(),
        ));
    app.update();
    app
}

fn counts(app: &mut App) -> (usize, usize) {
    let mut q = app
        .world_mut()
        .query::<(&RapierRigidBodySet, &RapierContextColliders)>();
    let (b, c) = q.single(app.world()).unwrap();
    (b.bodies.len(), c.colliders.len())
}

#[test]
fn every_shipped_scenario_ends_where_the_runner_ends() {
    for path in scenarios() {
        let scenario = Scenario::from_path(&path).unwrap();
        let steps = ((1.0 / scenario.world.dt).ceil() as u64).min(2000);

        let mut runner = Runner::new(scenario.build().unwrap());
        runner.run(steps);

        let mut app = app();
        spawn_scenario(app.world_mut(), &scenario).unwrap();
        let t0 = app.world().resource::<StickSlipRapier>().modifier().time();
        for _ in 0..steps {
            app.update();
        }
        let t = app.world().resource::<StickSlipRapier>().modifier().time() - t0;
        assert_eq!(
            t.to_bits(),
            runner.time().to_bits(),
            "{}: the same steps of the same length",
            path.display()
        );
        let loaded = app.world().resource::<LoadedScenario>().clone();
        let scene = runner.scene();
        let mut q = app.world_mut().query::<&RapierRigidBodySet>();
        let set = q.single(app.world()).unwrap();
        let (mut worst, mut identical) = (0.0f64, 0);
        for (b, s) in loaded.bodies.iter().zip(&scene.bodies) {
            assert_eq!(b.name, s.name);
            let handle = set.entity2body()[&b.entity];
            let ours = &set.bodies[handle];
            let theirs = &scene.world.bodies[s.handle];
            let (p, q) = (ours.translation(), theirs.translation());
            if p.to_array().map(f32::to_bits) == q.to_array().map(f32::to_bits)
                && ours.linvel().to_array().map(f32::to_bits)
                    == theirs.linvel().to_array().map(f32::to_bits)
            {
                identical += 1;
                continue;
            }
            let err = (p - q).abs().max_element() as f64;
            let travel = (q.to_array().map(f64::from).iter())
                .zip(s.start)
                .map(|(x, x0)| (x - x0).abs())
                .fold(0.0, f64::max);
            let speed = ours.linvel().length().max(theirs.linvel().length()) as f64;
            let tol = (1e-5 + 1e-3 * travel).max(2.0 * scenario.world.dt * speed);
            worst = worst.max(err / tol);
            assert!(
                err <= tol,
                "{}: body {} at {p:?} in bevy_rapier, {q:?} in the runner",
                path.display(),
                b.name,
            );
        }
        println!(
            "{}: {steps} steps, {identical} of {} bodies bit-identical, worst error of the \
             others {worst:.3} of the tolerance",
            path.file_name().unwrap().to_string_lossy(),
            loaded.bodies.len(),
        );
    }
}

#[test]
fn the_viewers_framing_shows_every_moving_body_whole() {
    let aspect = 16.0 / 9.0;
    let projection = PerspectiveProjection {
        aspect_ratio: aspect,
        ..default()
    };
    let clip_from_view = projection.get_clip_from_view();
    for path in scenarios() {
        let scenario = Scenario::from_path(&path).unwrap();
        let mut app = app();
        spawn_scenario(app.world_mut(), &scenario).unwrap();
        let loaded = app.world().resource::<LoadedScenario>();
        let camera = loaded.framing(projection.fov, aspect);
        let view_from_world = camera.to_matrix().inverse();
        let (min, max) = loaded.region;
        let (mut lo, mut hi) = (Vec2::splat(f32::MAX), Vec2::splat(f32::MIN));
        for i in 0..8 {
            let corner = Vec3::new(
                if i & 1 == 0 { min.x } else { max.x },
                if i & 2 == 0 { min.y } else { max.y },
                if i & 4 == 0 { min.z } else { max.z },
            );
            let ndc = clip_from_view.project_point3(view_from_world.transform_point3(corner));
            lo = lo.min(ndc.truncate());
            hi = hi.max(ndc.truncate());
        }
        println!(
            "{}: region {min:?}..{max:?} on screen x {:.2}..{:.2}, y {:.2}..{:.2}",
            path.file_name().unwrap().to_string_lossy(),
            lo.x,
            hi.x,
            lo.y,
            hi.y
        );
        assert!(
            lo.cmpge(Vec2::splat(-1.0)).all() && hi.cmple(Vec2::splat(1.0)).all(),
            "{}: cut off",
            path.display()
        );
        let span = (hi - lo).max_element();
        assert!(span >= 2.0 / 3.0, "{}: only {span} of 2", path.display());
    }
}

#[test]
fn reloading_replaces_the_entities() {
    let scenario = Scenario::builtin();
    let mut app = app();
    spawn_scenario(app.world_mut(), &scenario).unwrap();
    for _ in 0..3 {
        app.update();
    }
    let first = counts(&mut app);
    let old = app.world().resource::<LoadedScenario>().bodies[0].entity;
    assert!(first.0 > 0 && first.1 > 0);

    spawn_scenario(app.world_mut(), &scenario).unwrap();
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(counts(&mut app), first);
    assert!(
        app.world().get_entity(old).is_err(),
        "the old entities are gone"
    );
}

#[test]
fn an_invalid_scenario_is_an_error_and_spawns_nothing() {
    let mut scenario = Scenario::builtin();
    scenario.world.dt = -1.0;
    let mut app = app();
    let err = spawn_scenario(app.world_mut(), &scenario).unwrap_err();
    assert_eq!(err.field(), "world.dt");
    assert!(app.world().get_resource::<LoadedScenario>().is_none());
    app.update();
    app.update();
    assert_eq!(counts(&mut app), (0, 0));
}
