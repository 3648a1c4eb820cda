//! A recording decoded with rerun's own reader (`re_log_encoding`'s decoder and rerun's chunk
//! type, via `stickslip_rerun::inspect`) holds exactly what was simulated: the `step` and
//! `sim_time` timelines only, one pose row per logged step for every body with
//! sim_time = step·dt, every collider's shape (box, capsule, ball, mesh) statically, as many
//! contact points and friction arrows per logged step as the modifier reported, with class ids
//! equal to the reported regimes, regime-count series equal to the world totals, the
//! dissipated-energy series ending at the runner's total, body displacement series equal to the
//! bodies' displacement, the vibration series equal to the source's waveform at each logged
//! time, and per-contact series capped at the configured number; one rolling-resistance
//! torque arrow per resisting pair and logged step, classed by its rolling regime, and
//! torque series equal to the modifier's rolling reports. Holds for the `.rrd` file sink
//! and the in-memory sink.

use rapier3d::prelude::*;
use stickslip_core::law::{Coulomb, Law, Regime};
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier::{FrictionMaterial, StickSlip};
use stickslip_rerun::inspect::{self, RrdContents};
use stickslip_rerun::{LogOptions, RerunLogger, Sink, paths};
use stickslip_scenario::{Runner, Scenario};

fn scenario(name: &str) -> Scenario {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenarios")
        .join(format!("{name}.toml"));
    Scenario::from_path(path).unwrap()
}

/// What the simulation reported at each logged step.
#[derive(Default)]
struct Expected {
    steps: Vec<i64>,
    times: Vec<f64>,
    contacts: Vec<usize>,
    classes: Vec<Vec<u16>>,
    sticking: Vec<f64>,
    sliding: Vec<f64>,
    vibration: Vec<f64>,
}

/// Runs `name` for `steps` steps, logging every `every`-th (and step 0) to `sink`.
fn record(
    name: &str,
    steps: u64,
    every: u64,
    sink: Sink,
    max_contact_series: usize,
) -> (Runner, Expected, Option<stickslip_rerun::MemorySinkStorage>) {
    let scene = scenario(name).build().unwrap();
    let (rec, memory) = stickslip_rerun::open(&scene.name, &sink).unwrap();
    let mut logger = RerunLogger::new(
        rec,
        LogOptions {
            every,
            max_contact_series,
            ..LogOptions::default()
        },
    );
    for b in &scene.bodies {
        logger.set_body_name(b.handle, &b.name);
    }
    let vibrating = scene
        .colliders
        .iter()
        .find(|c| c.vibration.is_some())
        .map(|c| c.handle);
    let mut runner = Runner::new(scene);
    let mut exp = Expected::default();
    let note = |runner: &Runner, step: u64, exp: &mut Expected| {
        let s = runner.scene();
        exp.steps.push(step as i64);
        exp.times.push(s.stickslip.time());
        let reports = s.stickslip.reports().unwrap();
        exp.contacts.push(reports.len());
        exp.classes.push(
            reports
                .iter()
                .map(|r| stickslip_rerun::regime_class(r.regime))
                .collect(),
        );
        let count = |g: Regime| reports.iter().filter(|r| r.regime == g).count() as f64;
        exp.sticking.push(count(Regime::Sticking));
        exp.sliding.push(count(Regime::Sliding));
        if let Some(h) = vibrating {
            exp.vibration
                .push(s.stickslip.vibration(h).unwrap().signal(s.stickslip.time()));
        }
    };
    {
        let s = runner.scene();
        logger.log_step(0, &s.world, &s.stickslip).unwrap();
    }
    note(&runner, 0, &mut exp);
    for k in 1..=steps {
        runner.step();
        let s = runner.scene();
        if logger.log_step(k, &s.world, &s.stickslip).unwrap() {
            note(&runner, k, &mut exp);
        }
    }
    assert_eq!(logger.logged_steps() as usize, exp.steps.len());
    logger.flush().unwrap();
    drop(logger);
    (runner, exp, memory)
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

fn check(contents: &RrdContents, runner: &Runner, exp: &Expected, max_contact_series: usize) {
    let scene = runner.scene();
    // stickslip's viewer layout travels with the recording.
    assert!(contents.blueprint_chunks > 0, "no blueprint");
    assert_eq!(
        contents.application_ids,
        [scene.name.clone()].into_iter().collect()
    );
    assert_eq!(
        contents.timelines,
        [paths::STEP, paths::SIM_TIME]
            .into_iter()
            .map(String::from)
            .collect(),
        "only our two timelines"
    );
    // Bodies: one pose per logged step, sim_time = step·dt.
    let dt = scene.world.integration_parameters.dt as f64;
    for b in &scene.bodies {
        let e = contents
            .entity(&paths::body(&b.name))
            .unwrap_or_else(|| panic!("no entity for {}", b.name));
        assert_eq!(e.steps, exp.steps, "{}", b.name);
        assert!(close(&e.sim_times, &exp.times, 1e-6), "{}", b.name);
        let expected_times: Vec<f64> = exp.steps.iter().map(|&s| s as f64 * dt).collect();
        assert!(close(&e.sim_times, &expected_times, 1e-6));
        assert!(e.temporal_components.contains("Transform3D:translation"));
        assert!(e.temporal_components.contains("Transform3D:quaternion"));
    }
    // Colliders: static pose and shape.
    for c in &scene.colliders {
        let body = &scene.bodies[c.body];
        let path = paths::collider(&body.name, c.index);
        let e = contents
            .entity(&path)
            .unwrap_or_else(|| panic!("no {path}"));
        assert!(
            e.static_components.contains("Transform3D:translation"),
            "{path}"
        );
        let shape = match c.shape {
            stickslip_scenario::spec::ShapeSpec::Cuboid { .. } => "Boxes3D:half_sizes",
            stickslip_scenario::spec::ShapeSpec::Ball { .. } => "Ellipsoids3D:half_sizes",
            stickslip_scenario::spec::ShapeSpec::Capsule { .. } => "Capsules3D:lengths",
        };
        assert!(
            e.static_components.contains(shape),
            "{path}: {:?}",
            e.static_components
        );
        assert!(e.steps.is_empty(), "{path} is static only");
    }
    // Contacts: as many points and arrows as reports, classed by regime.
    let points = contents.entity(paths::CONTACT_POINTS).unwrap();
    assert_eq!(points.steps, exp.steps);
    assert_eq!(points.instances["Points3D:positions"], exp.contacts);
    assert_eq!(points.class_ids, exp.classes);
    let arrows = contents.entity(paths::FRICTION_ARROWS).unwrap();
    assert_eq!(arrows.instances["Arrows3D:vectors"], exp.contacts);
    assert!(
        contents
            .entity(paths::CONTACTS)
            .unwrap()
            .static_components
            .contains("AnnotationContext:context")
    );
    // World series.
    let sticking = contents.entity(&paths::world_series("sticking")).unwrap();
    assert_eq!(sticking.scalars, exp.sticking);
    assert!(sticking.static_components.contains("SeriesLines:names"));
    let sliding = contents.entity(&paths::world_series("sliding")).unwrap();
    assert_eq!(sliding.scalars, exp.sliding);
    let energy = contents
        .entity(&paths::world_series("dissipated_energy"))
        .unwrap();
    let summary = runner.summary();
    assert_eq!(energy.scalars.len(), exp.steps.len());
    let last = *energy.scalars.last().unwrap();
    assert!(
        (last - summary.dissipated_energy).abs() <= 1e-9 * summary.dissipated_energy.max(1.0),
        "{last} vs {}",
        summary.dissipated_energy
    );
    assert!(
        energy.scalars.windows(2).all(|w| w[1] >= w[0]),
        "energy never decreases"
    );
    // Body series: displacement ends at the body's displacement.
    for b in summary
        .bodies
        .iter()
        .take(LogOptions::default().max_body_series)
    {
        let e = contents
            .entity(&paths::body_series(&b.name, "displacement"))
            .unwrap_or_else(|| panic!("no displacement series for {}", b.name));
        let last = *e.scalars.last().unwrap();
        assert!(
            (last - b.distance).abs() < 1e-5,
            "{}: {last} vs {}",
            b.name,
            b.distance
        );
    }
    // Per-contact series: capped.
    let pairs: std::collections::BTreeSet<&str> = contents
        .children("series/contacts")
        .into_iter()
        .filter_map(|p| p.strip_prefix("series/contacts/")?.split('/').next())
        .collect();
    assert!(!pairs.is_empty());
    assert!(pairs.len() <= max_contact_series, "{pairs:?}");
    for pair in &pairs {
        for s in paths::CONTACT_SERIES {
            assert!(
                contents.entity(&paths::contact_series(pair, s)).is_some(),
                "{pair}/{s}"
            );
        }
    }
}

#[test]
fn rrd_file_holds_what_was_simulated() {
    let dir = std::env::temp_dir().join(format!("stickslip-rrd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("conveyor.rrd");
    let (runner, exp, _) = record("vibrating_conveyor", 60, 4, Sink::File(path.clone()), 3);
    assert_eq!(exp.steps, (0..=60).step_by(4).collect::<Vec<i64>>());
    let contents = inspect::read_rrd(&path).unwrap();
    println!(
        "{} chunks, {} entities, timelines {:?}",
        contents.chunks,
        contents.entities.len(),
        contents.timelines
    );
    check(&contents, &runner, &exp, 3);
    // The conveyor's parts touch the trough: contacts were logged, and the vibration signal is
    // the sine source sampled at the logged times.
    assert!(
        exp.contacts.iter().skip(1).all(|&n| n >= 5),
        "{:?}",
        exp.contacts
    );
    let vib = contents
        .entity(&paths::vibration_series("trough.0"))
        .expect("vibration series of the trough base");
    assert!(close(&vib.scalars, &exp.vibration, 1e-12));
    // The capsule is logged as a capsule, the multi-collider trough as four boxes.
    assert!(
        contents
            .entity(&paths::collider("pin", 0))
            .unwrap()
            .static_components
            .contains("Capsules3D:lengths")
    );
    assert_eq!(contents.children("world/bodies/trough").len(), 4);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn memory_sink_holds_what_was_simulated() {
    let (runner, exp, memory) = record("belt_stick_slip", 300, 25, Sink::Memory, 16);
    let bytes = memory.unwrap().drain_as_bytes().unwrap();
    let contents = inspect::read_rrd_bytes(&bytes).unwrap();
    check(&contents, &runner, &exp, 16);
    assert_eq!(exp.steps.len(), 13);
    // The belt block sticks, then slides: both regimes show in the recording.
    let sticking = &contents
        .entity(&paths::world_series("sticking"))
        .unwrap()
        .scalars;
    assert!(sticking.contains(&1.0));
    let speed = &contents
        .entity(&paths::body_series("block", "speed"))
        .unwrap()
        .scalars;
    assert!(
        speed
            .iter()
            .skip(2)
            .take(5)
            .all(|&v| (v - 0.1).abs() < 0.005),
        "rides with the belt at 0.1 m/s: {speed:?}"
    );
}

#[test]
fn balls_and_meshes_are_logged_as_such() {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_body(RigidBodyBuilder::fixed());
    let gc = world.insert_collider(ColliderBuilder::cuboid(5.0, 0.1, 5.0), Some(ground));
    let (ball, _) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.6, 0.0)),
        ColliderBuilder::ball(0.5),
    );
    let tri = world.insert_body(RigidBodyBuilder::fixed().translation(Vector::new(3.0, 0.0, 0.0)));
    world.insert_collider(
        ColliderBuilder::trimesh(
            vec![
                Vector::new(0.0, 0.0, 0.0),
                Vector::new(1.0, 0.0, 0.0),
                Vector::new(0.0, 0.0, 1.0),
            ],
            vec![[0, 1, 2]],
        )
        .unwrap(),
        Some(tri),
    );
    let mut friction = StickSlip::new(FrictionMaterial::new(Law::Coulomb(
        Coulomb::new(0.5).unwrap(),
    )))
    .with_read_back(stickslip_rapier::ReadBack::Contacts);
    friction.attach(&mut world.colliders, gc, None);
    let (rec, memory) = stickslip_rerun::open("shapes", &Sink::Memory).unwrap();
    let mut logger = RerunLogger::new(rec, LogOptions::default());
    logger.set_body_name(ball, "ball");
    logger.set_body_name(tri, "a mesh!");
    for k in 1..=5 {
        friction.step(&mut world);
        logger.log_step(k, &world, &friction).unwrap();
    }
    logger.flush().unwrap();
    let contents = inspect::read_rrd_bytes(&memory.unwrap().drain_as_bytes().unwrap()).unwrap();
    let ball_shape = contents.entity("world/bodies/ball/collider_0").unwrap();
    assert!(
        ball_shape
            .static_components
            .contains("Ellipsoids3D:half_sizes")
    );
    // Unsafe characters in names are replaced.
    let mesh = contents.entity("world/bodies/a_mesh_/collider_0").unwrap();
    assert!(mesh.static_components.contains("Mesh3D:vertex_positions"));
    let ground_name = logger.body_name(ground);
    assert!(contents.entity(&paths::body(&ground_name)).is_some());
    // Nothing resists rolling here: no torque arrows.
    assert!(contents.entity(paths::ROLLING_ARROWS).is_none());
    // The resting ball has one contact from the first step on.
    let points = contents.entity(paths::CONTACT_POINTS).unwrap();
    assert_eq!(points.steps, vec![1, 2, 3, 4, 5]);
    assert!(
        points.instances["Points3D:positions"]
            .iter()
            .skip(1)
            .all(|&n| n == 1)
    );
}

/// A ball rolling down a slope against rolling resistance: one torque arrow per logged step,
/// classed by its rolling regime, and the pair's torque series equal to what
/// `StickSlip::rolling_reports` gave at each step (the coefficient used at the law's μ_r). A
/// world without rolling resistance logs no torque arrows.
#[test]
fn rolling_resistance_torques_are_logged() {
    let mu_r = 0.02;
    let mut world = PhysicsWorld::default();
    let tan = 2.0 * mu_r;
    let theta = f64::atan(tan) as f32;
    world.gravity = Vector::new(9.81 * theta.sin(), -9.81 * theta.cos(), 0.0);
    let gc = world.insert_collider(ColliderBuilder::cuboid(50.0, 0.1, 5.0), None);
    let (ball, bc) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.2, 0.0)),
        ColliderBuilder::ball(0.1).density(1000.0),
    );
    let resist = Law::elasto_plastic(1e4, mu_r, mu_r, Curve::constant(mu_r).unwrap()).unwrap();
    let material = FrictionMaterial::new(Law::Coulomb(Coulomb::new(0.5).unwrap()))
        .with_rolling(resist.clone())
        .with_spinning(resist);
    let mut friction =
        StickSlip::new(material).with_read_back(stickslip_rapier::ReadBack::Contacts);
    friction.attach(&mut world.colliders, gc, None);
    friction.attach(&mut world.colliders, bc, None);
    let (rec, memory) = stickslip_rerun::open("rolling", &Sink::Memory).unwrap();
    let mut logger = RerunLogger::new(rec, LogOptions::default());
    logger.set_body_name(ball, "ball");
    let mut torques = Vec::new();
    for k in 1..=30 {
        friction.step(&mut world);
        let reports = friction.rolling_reports(&world.impulse_joints);
        if let [r] = reports[..] {
            let t = r.rolling_torque;
            torques.push(((t[0] * t[0] + t[1] * t[1] + t[2] * t[2]) as f64).sqrt());
        }
        logger.log_step(k, &world, &friction).unwrap();
    }
    logger.flush().unwrap();
    let contents = inspect::read_rrd_bytes(&memory.unwrap().drain_as_bytes().unwrap()).unwrap();
    let arrows = contents.entity(paths::ROLLING_ARROWS).unwrap();
    assert_eq!(arrows.steps.len(), torques.len());
    assert!(arrows.instances["Arrows3D:vectors"].iter().all(|&n| n == 1));
    // Rolling down above break-away: the law rolls (its sliding regime) once formed.
    let last = arrows.class_ids.last().unwrap();
    assert_eq!(last, &vec![stickslip_rerun::regime_class(Regime::Sliding)]);
    let path = contents
        .children("series/contacts")
        .into_iter()
        .find(|p| p.ends_with("/rolling_torque") && p.contains("ball"))
        .expect("the ball's pair has a rolling torque series")
        .to_string();
    let series = contents.entity(&path).unwrap();
    assert!(
        close(&series.scalars, &torques, 1e-6),
        "{:?} vs {torques:?}",
        series.scalars
    );
    let used = contents
        .entity(&path.replace("/rolling_torque", "/rolling_mu"))
        .unwrap();
    let last_mu = *used.scalars.last().unwrap();
    assert!((last_mu / mu_r - 1.0).abs() < 0.02, "μ_r used {last_mu}");
}
