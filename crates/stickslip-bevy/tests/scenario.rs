//! A scenario file behaves the same in bevy as in `stickslip run`: every shipped scenario
//! (`scenarios/*.toml`), spawned as entities by `spawn_scenario` and stepped by the plugins
//! with its drivers, ends where the scenario crate's headless `Runner` ends after a second of
//! simulated time: the same steps, and every body's rapier position and velocity bit for bit
//! — or, where rapier's broad phase pairs two colliders the other way round than in the
//! runner (the plugin registers them in another order; the contact normal is then flipped,
//! which changes the solver's rounding by ulps, and a stick-slip event on a step boundary may
//! then happen one step apart), within 10 µm + 0.1 % of its travel or two steps of its motion
//! (2·dt·|v|): a box held on a vibrating trough wanders by micrometres across it, which way
//! depends on those ulps. The test prints how many bodies are bit-identical. Reloading a scenario replaces its entities and leaves no rapier object behind.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use std::path::PathBuf;
use stickslip_bevy::prelude::*;
use stickslip_bevy::scenario::{LoadedScenario, Scenario, StickSlipScenarioPlugin, spawn_scenario};
use stickslip_scenario::Runner;

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
    app.add_plugins((
        MinimalPlugins,
        StickSlipPlugins::default(),
        StickSlipScenarioPlugin::default(),
    ))
    .insert_resource(TimeUpdateStrategy::FixedTimesteps(1));
    app
}

#[test]
fn every_shipped_scenario_ends_where_the_runner_ends() {
    for path in scenarios() {
        let scenario = Scenario::from_path(&path).unwrap();
        let steps = (1.0 / scenario.world.dt).ceil() as u64;

        let mut runner = Runner::new(scenario.build().unwrap());
        runner.run(steps);

        let mut app = app();
        spawn_scenario(app.world_mut(), &scenario).unwrap();
        app.update(); // no time step yet
        for _ in 0..steps {
            app.update();
        }
        let w = app.world().resource::<StickSlipWorld>();
        assert_eq!(
            w.friction.time().to_bits(),
            runner.time().to_bits(),
            "{}: the same steps of the same length",
            path.display()
        );
        let loaded = app.world().resource::<LoadedScenario>();
        let scene = runner.scene();
        let (mut worst, mut identical) = (0.0f64, 0);
        for (b, s) in loaded.bodies.iter().zip(&scene.bodies) {
            assert_eq!(b.name, s.name);
            let ours = &w.physics.bodies[w.body(b.entity).unwrap()];
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
                "{}: body {} at {p:?} in bevy, {q:?} in the runner",
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
fn reloading_replaces_the_entities() {
    let scenario = Scenario::builtin();
    let mut app = app();
    spawn_scenario(app.world_mut(), &scenario).unwrap();
    for _ in 0..3 {
        app.update();
    }
    let w = app.world().resource::<StickSlipWorld>();
    let first = (w.physics.bodies.len(), w.physics.colliders.len());
    let old = app.world().resource::<LoadedScenario>().bodies[0].entity;
    assert!(first.0 > 0 && first.1 > 0);

    spawn_scenario(app.world_mut(), &scenario).unwrap();
    for _ in 0..3 {
        app.update();
    }
    let w = app.world().resource::<StickSlipWorld>();
    assert_eq!((w.physics.bodies.len(), w.physics.colliders.len()), first);
    assert_eq!(w.counts(), first);
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
    assert_eq!(app.world().resource::<StickSlipWorld>().counts(), (0, 0));
}
