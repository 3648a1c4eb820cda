//! Snapshot and restore of a rapier2d world with stickslip. Invariant: a world saved
//! mid-run — through bytes and a file (`WorldSnapshot`), and in memory (`StickSlip::snapshot`
//! / `StickSlip::restore` beside a deserialized rapier2d world) — and resumed from a freshly
//! deserialized world and a fresh modifier continues bit for bit like the uninterrupted run:
//! every body's pose and velocity, every contact report and the world totals are identical
//! (`to_bits`) at each of 1 000 steps after the restore, for the EP, Phys and Regul laws
//! with time-resolved and averaged vibration (normal on the ground, tangential on the belt),
//! a wrapped conveyor hook, and contacts appearing and disappearing (boxes pushed off the
//! ground's edge onto a floor, hopping, some sleeping). A modifier restarted without the saved
//! state diverges (so the comparison can fail). Garbage and truncated bytes give an error,
//! never a panic.

mod support;

use stickslip_rapier2d::core::law::{Law, Physical, Regularization, Regularized};
use stickslip_rapier2d::core::sliding_curve::{Curve, StribeckDecay};
use stickslip_rapier2d::core::waveform::Waveform;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{
    Amplitude, ContactReport, FrictionMaterial, ReadBack, StickSlip, StickSlipSnapshot,
    VibrationDirection, VibrationMode, VibrationSource, WorldSnapshot, WorldTotals,
};
use support::Conveyor;

/// Steps before the snapshot, and after it.
const BEFORE: usize = 150;
const AFTER: usize = 1000;

#[derive(Clone, Copy, Debug)]
enum Kind {
    Ep,
    Phys,
    Regul,
}

fn law(kind: Kind) -> Law {
    let stribeck = Curve::stribeck(0.6, 0.4, 0.05, StribeckDecay::Exponential, 0.01).unwrap();
    match kind {
        Kind::Ep => Law::elasto_plastic(2e3, 0.5, 0.6, stribeck).unwrap(),
        Kind::Phys => Law::Physical(Physical::new(0.5, stribeck).unwrap()),
        Kind::Regul => {
            Law::Regularized(Regularized::new(stribeck, 1e-3, Regularization::Tanh).unwrap())
        }
    }
}

struct Scene {
    world: PhysicsWorld,
    bodies: Vec<RigidBodyHandle>,
    ground: ColliderHandle,
    floor: ColliderHandle,
    belt: ColliderHandle,
}

/// A ground slab above a wide floor, a belt beside it, and boxes that are dropped, pushed
/// off the ground's edge, hop and rest (some may sleep).
fn scene() -> Scene {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(ColliderBuilder::cuboid(2.5, 0.1).restitution(0.3), None);
    // Boxes that leave the ground land here (new contacts, same stickslip material).
    let floor = world.insert_collider(
        ColliderBuilder::cuboid(50.0, 0.1).translation(Vector::new(0.0, -3.0)),
        None,
    );
    let belt = world.insert_collider(
        ColliderBuilder::cuboid(1.5, 0.1).translation(Vector::new(8.0, 0.0)),
        None,
    );
    let mut bodies = Vec::new();
    for i in 0..8 {
        let x = if i < 6 {
            -1.5 + 0.6 * i as f32
        } else {
            7.6 + 0.6 * (i - 6) as f32
        };
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, 0.3 + 0.25 * i as f32))
                .rotation(0.05 * i as f32)
                .linvel(Vector::new(0.05 * i as f32, 0.0))
                .can_sleep(i % 3 == 0),
            ColliderBuilder::cuboid(0.15, 0.15)
                .density(500.0 + 100.0 * i as f32)
                .restitution(0.2),
        );
        bodies.push(b);
    }
    Scene {
        world,
        bodies,
        ground,
        floor,
        belt,
    }
}

type Modifier = StickSlip<Conveyor>;

fn modifier(kind: Kind, mode: VibrationMode, s: &mut Scene) -> Modifier {
    let conveyor = Conveyor {
        belt: s.belt,
        velocity: Vector::new(0.3, 0.0),
    };
    // The user flags the belt for their hook, as they would without stickslip.
    s.world.colliders[s.belt].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(law(kind)), conveyor)
        .with_read_back(ReadBack::Contacts);
    m.attach(&mut s.world.colliders, s.ground, None);
    m.attach(&mut s.world.colliders, s.floor, None);
    let belt_law = Law::elasto_plastic(5e3, 0.7, 0.7, Curve::constant(0.7).unwrap()).unwrap();
    m.attach(
        &mut s.world.colliders,
        s.belt,
        Some(FrictionMaterial::new(belt_law)),
    );
    // Time-resolved sources must be resolved by dt = 1/60; averaged ones are ultrasonic.
    let f = match mode {
        VibrationMode::TimeResolved => 2.5,
        VibrationMode::Averaged => 2e4,
    };
    let normal = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.4),
        f,
        Waveform::Sine,
        0.1,
        mode,
    )
    .unwrap();
    let table = Waveform::from_table(&[0.0, 2.0, 0.5, 1.7, 0.2]).unwrap();
    let in_plane = VibrationSource::new(
        VibrationDirection::Tangential {
            axis: [1.0, 0.0, 0.0],
        },
        Amplitude::Force(20.0),
        f * 1.3,
        table,
        0.25,
        mode,
    )
    .unwrap()
    .with_tangential_stiffness(3e4)
    .unwrap();
    m.set_vibration(s.ground, normal);
    m.set_vibration(s.belt, in_plane);
    m
}

/// Deterministic pushes: back and forth beyond break-away at the peaks (stick-slip), with a
/// drift toward the +x edge for two boxes (they slide off and fall, one before the snapshot,
/// one after), and lifts that make boxes hop (contacts vanish and re-form).
fn push(world: &mut PhysicsWorld, bodies: &[RigidBodyHandle], k: usize) {
    for (i, b) in bodies.iter().enumerate() {
        let body = &mut world.bodies[*b];
        let m = body.mass();
        let phase = k as f32 * 0.03 + i as f32;
        let bias = match i {
            5 => 0.25,
            4 => 0.12,
            _ => 0.0,
        };
        let fx = m * 9.81 * (bias + 0.52 * phase.sin());
        let lift = if (k + 40 * i) % 300 < 12 { 14.0 } else { 0.0 };
        body.reset_forces(false);
        if body.is_sleeping() && i % 2 == 0 {
            continue; // some sleeping bodies stay asleep
        }
        body.add_force(Vector::new(fx, m * lift), true);
    }
}

fn step(world: &mut PhysicsWorld, bodies: &[RigidBodyHandle], m: &mut Modifier, k: usize) {
    push(world, bodies, k);
    m.step(world);
}

/// Bits of everything observable after a step: bodies, reports, totals, time.
fn state(world: &PhysicsWorld, bodies: &[RigidBodyHandle], m: &Modifier) -> Vec<u64> {
    let mut out = Vec::new();
    for b in bodies {
        let b = &world.bodies[*b];
        let p = b.position();
        let r = p.rotation;
        let vals = [
            p.translation.x,
            p.translation.y,
            r.cos(),
            r.sin(),
            b.linvel().x,
            b.linvel().y,
            b.angvel(),
        ];
        out.extend(vals.map(|x| x.to_bits() as u64));
        out.push(b.is_sleeping() as u64);
    }
    out.push(m.reports().unwrap().len() as u64);
    for r in m.reports().unwrap() {
        out.extend(report_bits(r));
    }
    out.extend(totals_bits(&m.totals().unwrap()));
    out.push(m.time().to_bits());
    out
}

fn report_bits(r: &ContactReport) -> Vec<u64> {
    let (a, b) = (
        r.collider1.0.into_raw_parts(),
        r.collider2.0.into_raw_parts(),
    );
    let mut v = vec![
        a.0 as u64,
        a.1 as u64,
        b.0 as u64,
        b.1 as u64,
        r.regime as u64,
        r.reset as u64,
    ];
    for x in [r.point, r.normal, r.friction_force, r.slip_velocity] {
        v.extend(x.map(|x| x.to_bits() as u64));
    }
    v.extend([r.mu, r.limit, r.normal_force, r.dissipated_power].map(f64::to_bits));
    v
}

fn totals_bits(t: &WorldTotals) -> Vec<u64> {
    let mut v = vec![
        t.contacts as u64,
        t.sticking as u64,
        t.stick_slip as u64,
        t.sliding as u64,
        t.reset as u64,
    ];
    v.extend(
        [
            t.normal_force,
            t.friction_force,
            t.dissipated_power,
            t.dissipated_energy,
        ]
        .map(f64::to_bits),
    );
    v
}

fn world_bytes(world: &PhysicsWorld, m: &Modifier) -> Vec<u8> {
    let mut bytes = Vec::new();
    WorldSnapshot::save_from(world, m, &mut bytes).unwrap();
    bytes
}

fn run_case(kind: Kind, mode: VibrationMode) {
    let mut s = scene();
    let mut m = modifier(kind, mode, &mut s);
    for k in 0..BEFORE {
        step(&mut s.world, &s.bodies, &mut m, k);
    }
    let contacts_at_snapshot = m.active_contacts();
    assert!(
        contacts_at_snapshot >= 4,
        "{kind:?}: {contacts_at_snapshot} contacts"
    );
    // Through bytes.
    let bytes = world_bytes(&s.world, &m);
    let (mut w_bytes, mut m_bytes) = WorldSnapshot::load(bytes.as_slice())
        .unwrap()
        .restore(*m.inner())
        .unwrap();
    // In memory: the modifier's snapshot object, rapier2d's world through bytes (it has no
    // Clone).
    let in_memory: StickSlipSnapshot = m.snapshot();
    let mut w_mem = WorldSnapshot::load(bytes.as_slice()).unwrap().world;
    let mut m_mem = StickSlip::restore(&in_memory, &w_mem.colliders, *m.inner()).unwrap();
    // Through a file.
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("snapshot-2d-{kind:?}-{mode:?}.bin"));
    WorldSnapshot::save_from(&s.world, &m, std::fs::File::create(&path).unwrap()).unwrap();
    let (mut w_file, mut m_file) = WorldSnapshot::load(std::fs::File::open(&path).unwrap())
        .unwrap()
        .restore(*m.inner())
        .unwrap();
    std::fs::remove_file(&path).ok();
    // A restored modifier reports what the original reported.
    assert_eq!(
        state(&w_file, &s.bodies, &m_file),
        state(&s.world, &s.bodies, &m)
    );
    assert_eq!(m_file.active_contacts(), contacts_at_snapshot);
    // Control: the same world resumed with a fresh modifier (same materials, sources, time)
    // that lost the contact state. It must diverge, or this test proves nothing.
    let mut lost_scene = Scene {
        world: WorldSnapshot::load(bytes.as_slice()).unwrap().world,
        bodies: s.bodies.clone(),
        ground: s.ground,
        floor: s.floor,
        belt: s.belt,
    };
    let mut lost = modifier(kind, mode, &mut lost_scene);
    lost.set_time(m.time());
    let mut w_lost = lost_scene.world;
    let mut diverged = false;

    let (mut min_reports, mut max_reports) = (usize::MAX, 0);
    let on_ground = |w: &PhysicsWorld| {
        s.bodies
            .iter()
            .filter(|b| w.bodies[**b].translation().y > -1.0)
            .count()
    };
    let on_ground_at_snapshot = on_ground(&s.world);
    for k in BEFORE..BEFORE + AFTER {
        step(&mut s.world, &s.bodies, &mut m, k);
        step(&mut w_bytes, &s.bodies, &mut m_bytes, k);
        step(&mut w_mem, &s.bodies, &mut m_mem, k);
        step(&mut w_file, &s.bodies, &mut m_file, k);
        step(&mut w_lost, &s.bodies, &mut lost, k);
        let want = state(&s.world, &s.bodies, &m);
        assert!(
            want == state(&w_bytes, &s.bodies, &m_bytes),
            "{kind:?} {mode:?}: restore from bytes differs at step {k}"
        );
        assert!(
            want == state(&w_mem, &s.bodies, &m_mem),
            "{kind:?} {mode:?}: in-memory restore differs at step {k}"
        );
        assert!(
            want == state(&w_file, &s.bodies, &m_file),
            "{kind:?} {mode:?}: file restore differs at step {k}"
        );
        diverged |= want != state(&w_lost, &s.bodies, &lost);
        min_reports = min_reports.min(m.reports().unwrap().len());
        max_reports = max_reports.max(m.reports().unwrap().len());
    }
    let fell = on_ground_at_snapshot - on_ground(&s.world);
    assert!(
        diverged,
        "{kind:?} {mode:?}: a modifier without the saved state did not diverge"
    );
    assert!(
        min_reports < max_reports,
        "{kind:?} {mode:?}: contacts {min_reports}..{max_reports}: none appeared or vanished"
    );
    assert!(
        fell >= 1,
        "{kind:?} {mode:?}: no box left the ground after the snapshot"
    );
    assert_eq!(m.active_contacts(), m_file.active_contacts());
    assert!(m.totals().unwrap().dissipated_energy > 0.0);
    println!(
        "{kind:?} {mode:?}: {contacts_at_snapshot} contacts at the snapshot ({} bytes), \
         {min_reports}..{max_reports} reported after, {fell} boxes fell, identical over {AFTER} \
         steps",
        bytes.len()
    );
}

#[test]
fn ep_time_resolved_vibration_resumes_bit_identically() {
    run_case(Kind::Ep, VibrationMode::TimeResolved);
}

#[test]
fn ep_averaged_vibration_resumes_bit_identically() {
    run_case(Kind::Ep, VibrationMode::Averaged);
}

#[test]
fn phys_time_resolved_vibration_resumes_bit_identically() {
    run_case(Kind::Phys, VibrationMode::TimeResolved);
}

#[test]
fn phys_averaged_vibration_resumes_bit_identically() {
    run_case(Kind::Phys, VibrationMode::Averaged);
}

#[test]
fn regul_time_resolved_vibration_resumes_bit_identically() {
    run_case(Kind::Regul, VibrationMode::TimeResolved);
}

#[test]
fn regul_averaged_vibration_resumes_bit_identically() {
    run_case(Kind::Regul, VibrationMode::Averaged);
}

#[test]
fn garbage_and_truncated_bytes_are_errors_not_panics() {
    let mut s = scene();
    let mut m = modifier(Kind::Ep, VibrationMode::Averaged, &mut s);
    for k in 0..100 {
        step(&mut s.world, &s.bodies, &mut m, k);
    }
    let bytes = world_bytes(&s.world, &m);
    let restore = |b: &[u8]| WorldSnapshot::load(b).and_then(|w| w.restore(()));
    assert!(restore(&bytes).is_ok());
    assert!(restore(b"not a snapshot at all").is_err());
    assert!(restore(&[]).is_err());
    // Every truncation (a few hundred cut points) is an error.
    let cuts = bytes.len() / 200 + 1;
    for end in (0..bytes.len()).step_by(cuts) {
        assert!(restore(&bytes[..end]).is_err(), "truncated at {end} loaded");
    }
    // Flipped bytes: an error or a valid world, never a panic.
    let mut rng = 0x9e3779b97f4a7c15u64;
    for _ in 0..200 {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let mut mutated = bytes.clone();
        let i = 13 + (rng as usize) % (bytes.len() - 13);
        mutated[i] ^= 1 << ((rng >> 32) % 8);
        let _ = restore(&mutated);
    }
}

#[test]
fn quiet_recycled_contacts_resume_bit_identically() {
    // Boxes resting on an attached ground with nothing driving them: stickslip turns its hook
    // flag off on their colliders (rapier2d recycles their contacts). Saved in that state, the
    // world resumes bit for bit, also when a box is pushed awake and the pushes end.
    let build = || {
        let mut world = PhysicsWorld::default();
        let ground = world.insert_collider(ColliderBuilder::cuboid(20.0, 0.1), None);
        let mut bodies = Vec::new();
        let mut colliders = vec![ground];
        for i in 0..5 {
            let (b, c) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(-4.0 + 2.0 * i as f32, 0.1 + 0.25 + 0.01))
                    .rotation(0.0)
                    .can_sleep(false),
                ColliderBuilder::cuboid(0.25, 0.25).density(800.0),
            );
            bodies.push(b);
            colliders.push(c);
        }
        // A second layer on the middle box.
        let (b, c) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 0.85 + 0.02))
                .can_sleep(false),
            ColliderBuilder::cuboid(0.2, 0.2).density(800.0),
        );
        bodies.push(b);
        colliders.push(c);
        let mut m =
            StickSlip::new(FrictionMaterial::new(law(Kind::Ep))).with_read_back(ReadBack::Contacts);
        for h in &colliders {
            m.attach(&mut world.colliders, *h, None);
        }
        (world, bodies, colliders, m)
    };
    let (mut world, bodies, colliders, mut m) = build();
    for _ in 0..240 {
        m.step(&mut world);
    }
    let recycled = colliders.iter().filter(|c| m.is_recycled(**c)).count();
    println!(
        "{recycled} of {} colliders recycled at the snapshot",
        colliders.len()
    );
    assert!(recycled >= 3, "the resting scene is not quiet");
    let bytes = {
        let mut b = Vec::new();
        WorldSnapshot::save_from(&world, &m, &mut b).unwrap();
        b
    };
    let (mut w2, mut m2) = WorldSnapshot::load(bytes.as_slice())
        .unwrap()
        .restore(())
        .unwrap();
    for c in &colliders {
        assert_eq!(m.is_recycled(*c), m2.is_recycled(*c));
    }
    let bits = |w: &PhysicsWorld, m: &StickSlip| {
        let mut out: Vec<u64> = Vec::new();
        for b in &bodies {
            let b = &w.bodies[*b];
            let p = b.position();
            let v = [
                p.translation.x,
                p.translation.y,
                p.rotation.cos(),
                p.rotation.sin(),
                b.linvel().x,
                b.linvel().y,
                b.angvel(),
            ];
            out.extend(v.map(|x| x.to_bits() as u64));
        }
        for r in m.reports().unwrap() {
            out.extend(report_bits(r));
        }
        out
    };
    let mut woke = false;
    for k in 0..600 {
        for (w, m) in [(&mut world, &mut m), (&mut w2, &mut m2)] {
            // A push on box 1 from 1 s to 1.5 s after the snapshot, beyond break-away.
            let b = &mut w.bodies[bodies[1]];
            b.reset_forces(true);
            if (60..90).contains(&k) {
                let f = 0.8 * b.mass() * 9.81;
                b.add_force(Vector::new(f, 0.0), true);
            }
            m.step(w);
        }
        woke |= !m.is_recycled(colliders[2]);
        assert!(
            bits(&world, &m) == bits(&w2, &m2),
            "the quiet world resumed differently at step {k}"
        );
    }
    assert!(woke, "the pushed box's contact was never hooked again");
    let recycled_end = colliders.iter().filter(|c| m.is_recycled(**c)).count();
    println!("identical over 600 steps; {recycled_end} recycled at the end");
}
