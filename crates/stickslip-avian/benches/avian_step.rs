//! Step cost of stickslip in avian beside plain avian, in the same run: 400 boxes resting on a
//! floor, and 400 boxes sliding down a slope, with avian's `Friction::new(0.4)
//! .with_static_coefficient(0.6)` (stickslip's "Phys" on every pair) and with stickslip's
//! default EP material on every collider. Sleeping is off, so every contact is solved every
//! tick. `scripts/bench_report.sh` puts the ratios into BENCHMARKS.md.

use avian3d::prelude::*;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy::transform::TransformPlugin;
use criterion::{Criterion, criterion_group, criterion_main};
use std::time::Duration;
use stickslip_avian::{StickSlipAvianPlugin, StickSlipFriction};

/// How the friction is set up.
#[derive(Clone, Copy)]
enum Setup {
    /// Plain avian, the same `Friction` components.
    Plain,
    /// stickslip: avian's static coefficient made real.
    StaticCoefficient,
    /// stickslip: the default EP material on every collider.
    Ep,
}

fn scene(setup: Setup, side: usize, tan: f64) -> App {
    let mut app = App::new();
    let theta = tan.atan();
    app.add_plugins((MinimalPlugins, TransformPlugin, PhysicsPlugins::default()))
        .insert_resource(Time::<Fixed>::from_hz(60.0))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 60.0,
        )))
        .insert_resource(Gravity(Vec3::new(
            (9.81 * theta.sin()) as f32,
            -(9.81 * theta.cos()) as f32,
            0.0,
        )));
    if !matches!(setup, Setup::Plain) {
        app.add_plugins(StickSlipAvianPlugin::default());
    }
    app.finish();
    app.cleanup();
    let friction = Friction::new(0.4).with_static_coefficient(0.6);
    let world = app.world_mut();
    let floor = world
        .spawn((
            RigidBody::Static,
            Collider::cuboid(100_000.0, 0.2, 1000.0),
            Transform::from_xyz(0.0, -0.1, 0.0),
            friction,
        ))
        .id();
    let mut bodies = vec![floor];
    for i in 0..side {
        for j in 0..side {
            bodies.push(
                world
                    .spawn((
                        RigidBody::Dynamic,
                        Collider::cuboid(0.5, 0.5, 0.5),
                        Transform::from_xyz(i as f32 * 1.5, 0.25, j as f32 * 1.5),
                        SleepingDisabled,
                        friction,
                    ))
                    .id(),
            );
        }
    }
    if matches!(setup, Setup::Ep) {
        for e in bodies {
            world.entity_mut(e).insert(StickSlipFriction(None));
        }
    }
    for _ in 0..60 {
        app.update();
    }
    app
}

fn bench_scene(c: &mut Criterion, name: &str, tan: f64) {
    // STICKSLIP_BENCH_QUICK (the CI smoke run) shrinks the scene.
    let side = if std::env::var_os("STICKSLIP_BENCH_QUICK").is_some() {
        4
    } else {
        20
    };
    let mut group = c.benchmark_group(format!("{name}_{}", side * side));
    for (label, setup) in [
        ("plain_avian", Setup::Plain),
        ("static_coefficient", Setup::StaticCoefficient),
        ("ep", Setup::Ep),
    ] {
        let mut app = scene(setup, side, tan);
        group.bench_function(label, |b| b.iter(|| app.update()));
    }
    group.finish();
}

fn avian_step(c: &mut Criterion) {
    bench_scene(c, "avian_rest", 0.0);
    bench_scene(c, "avian_slide", 0.8);
}

criterion_group!(benches, avian_step);
criterion_main!(benches);
