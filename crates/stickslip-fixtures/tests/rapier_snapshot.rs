//! Snapshot and restore. Invariant: a world with stickslip friction saved after some steps —
//! in memory (`StickSlip::snapshot`/`restore`) or through bytes and a file (`WorldSnapshot`)
//! — and resumed from a freshly deserialized rapier world and a fresh modifier continues
//! bit for bit like the uninterrupted run: every body's pose and velocity, every contact
//! report and the world totals are identical (`to_bits`) at each of 1 000 steps after the
//! restore, for the EP, Phys and Regul laws, with time-resolved and averaged vibration,
//! user hooks wrapped, and contacts appearing and disappearing (boxes pushed off the edge
//! of the ground, bouncing, landing, sleeping). A modifier restarted without the saved state
//! diverges (so the comparison can fail). Garbage, truncated and mutated snapshot bytes, and
//! inconsistent snapshot data, give an error and never a panic. Contacts recycled while
//! quiet resume bit for bit as well, and so do balls with rolling and spinning resistance
//! (the world's resisting joints kept with their states; without those states the run
//! diverges). All in 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::law::{Law, Physical, Regularization, Regularized};
use stickslip_core::sliding_curve::{Curve, StribeckDecay};
use stickslip_core::waveform::Waveform;
use stickslip_fixtures::dim::body_bits;
use stickslip_fixtures::{Conveyor, cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::snapshot::SnapshotError;
use stickslip_rapier::{
    Amplitude, ContactReport, FrictionMaterial, StickSlip, StickSlipSnapshot, VibrationDirection,
    VibrationMode, VibrationSource, WorldSnapshot, WorldTotals,
};

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

/// A ground slab (stickslip, normal vibration) above a wide floor, a fixed belt beside it (its own material, an
/// in-plane vibration, a conveyor hook), and boxes that are dropped, pushed off the ground's
/// edge, bounce and rest (some may sleep).
fn scene() -> Scene {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(cuboid3(2.5, 0.1, 2.0).0.restitution(0.3), None);
    // Boxes that leave the ground land here (new contacts, same stickslip material).
    let floor = world.insert_collider(
        cuboid3(50.0, 0.1, 50.0).0.translation(v3(0.0, -3.0, 0.0)),
        None,
    );
    // The belt: beside the ground along z in 3D, along x in 2D.
    #[cfg(not(dim2))]
    let (belt_half, belt_at, belt_x0, belt_z) = (1.0, v3(0.0, 0.0, 4.0), -0.3, 4.0);
    #[cfg(dim2)]
    let (belt_half, belt_at, belt_x0, belt_z) = (1.5, v3(8.0, 0.0, 0.0), 7.6, 0.0);
    let belt = world.insert_collider(cuboid3(belt_half, 0.1, 1.0).0.translation(belt_at), None);
    let mut bodies = Vec::new();
    for i in 0..8 {
        let (x, z) = if i < 6 {
            (-1.5 + 0.6 * i as f32, 0.0)
        } else {
            (belt_x0 + 0.6 * (i - 6) as f32, belt_z)
        };
        #[cfg(not(dim2))]
        let tilt = Vector::new(0.0, 0.3 * i as f32, 0.05 * i as f32);
        #[cfg(dim2)]
        let tilt = 0.05 * i as f32;
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(x, 0.3 + 0.25 * i as f32, z + 0.1 * (i as f32).sin()))
                .rotation(tilt)
                .linvel(v3(0.05 * i as f32, 0.0, 0.0))
                .can_sleep(i % 3 == 0),
            cuboid3(0.15, 0.15, 0.15)
                .0
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
        velocity: v3(0.3, 0.0, 0.0),
    };
    // The user flags the belt for their hook, as they would without stickslip.
    s.world.colliders[s.belt].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(law(kind)), conveyor)
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
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
            // (2D: the tangent line's direction, x.)
            axis: [1.0, 0.0, if cfg!(dim2) { 0.0 } else { 0.3 }],
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
/// drift toward the +x edge for the two outer boxes (they slide off and fall, one before the
/// snapshot, one after), and lifts that make boxes hop (contacts vanish and re-form).
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
        body.add_force(v3(fx, m * lift, 0.1 * fx), true);
    }
}

fn step(s: &mut PhysicsWorld, bodies: &[RigidBodyHandle], m: &mut Modifier, k: usize) {
    push(s, bodies, k);
    m.step(s);
}

/// Bits of everything observable after a step: bodies, reports, totals.
fn state(world: &PhysicsWorld, bodies: &[RigidBodyHandle], m: &Modifier) -> Vec<u64> {
    let mut out = Vec::new();
    for b in bodies {
        let b = &world.bodies[*b];
        out.extend(body_bits(b).into_iter().map(u64::from));
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

    // In memory: the modifier's snapshot object, rapier's world through bytes (rapier's world
    // has no Clone).
    let in_memory: StickSlipSnapshot = m.snapshot();
    let bytes = world_bytes(&s.world, &m);
    // Through bytes: the world and the modifier together.
    let (mut w_bytes, mut m_bytes) = WorldSnapshot::load(bytes.as_slice())
        .unwrap()
        .restore(*m.inner())
        .unwrap();
    let loaded = WorldSnapshot::load(bytes.as_slice()).unwrap();
    let mut w_mem = loaded.world;
    let mut m_mem = StickSlip::restore(&in_memory, &w_mem.colliders, *m.inner()).unwrap();
    // Through a file.
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("snapshot-{kind:?}-{mode:?}.bin"));
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
    // Control: the same world resumed with a modifier that lost its state (fresh modifier
    // with the same materials, sources and time). It must diverge, or this test proves nothing.
    let mut w_lost = WorldSnapshot::load(bytes.as_slice()).unwrap().world;
    let mut lost = {
        let mut sc = Scene {
            world: std::mem::take(&mut w_lost),
            bodies: s.bodies.clone(),
            ground: s.ground,
            floor: s.floor,
            belt: s.belt,
        };
        let mut l = modifier(kind, mode, &mut sc);
        l.set_time(m.time());
        w_lost = sc.world;
        l
    };
    let mut diverged = false;

    let (mut min_reports, mut max_reports) = (usize::MAX, 0);
    let capacity_before = m.state_capacity();
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
    // Contacts appeared and disappeared after the restore.
    assert!(
        min_reports < max_reports,
        "{kind:?} {mode:?}: contacts {min_reports}..{max_reports}"
    );
    assert!(
        fell >= 1,
        "{kind:?} {mode:?}: no box left the ground after the snapshot"
    );
    assert!(m.state_capacity() >= capacity_before);
    assert_eq!(m.active_contacts(), m_file.active_contacts());
    assert!(m.totals().unwrap().dissipated_energy > 0.0);
    eprintln!(
        "{kind:?} {mode:?}: {contacts_at_snapshot} contacts at the snapshot ({} bytes), \
         {min_reports}..{max_reports} reported after, {fell} boxes fell, identical over {AFTER} steps",
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

/// A snapshot with live contacts, free slots and every kind of table: taken at the first step
/// after 100 at which a contact has vanished and left its slot free.
fn busy_snapshot() -> (Vec<u8>, StickSlipSnapshot, PhysicsWorld) {
    let mut s = scene();
    let mut m = modifier(Kind::Ep, VibrationMode::Averaged, &mut s);
    let mut k = 0;
    while k < 100 || m.state_capacity() == m.active_contacts() {
        step(&mut s.world, &s.bodies, &mut m, k);
        k += 1;
        assert!(k < 3000, "no contact vanished");
    }
    assert!(m.active_contacts() > 0);
    let bytes = world_bytes(&s.world, &m);
    (bytes, m.snapshot(), s.world)
}

/// Deterministic pseudo-random numbers (xorshift).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

fn load_and_restore(bytes: &[u8]) -> Result<(PhysicsWorld, StickSlip<()>), SnapshotError> {
    WorldSnapshot::load(bytes)?.restore(())
}

#[test]
fn garbage_truncated_and_mutated_bytes_are_errors_not_panics() {
    let (bytes, _, _) = busy_snapshot();
    assert!(load_and_restore(&bytes).is_ok());
    // Not a snapshot at all.
    assert!(matches!(
        load_and_restore(&[]),
        Err(SnapshotError::NotASnapshot)
    ));
    assert!(matches!(
        load_and_restore(b"{\"world\": 1}"),
        Err(SnapshotError::NotASnapshot)
    ));
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for len in [13, 14, 100, 5000] {
        let mut g: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        assert!(load_and_restore(&g).is_err());
        g[..13].copy_from_slice(&bytes[..13]); // a valid header, garbage after it
        assert!(load_and_restore(&g).is_err(), "garbage of {len} bytes");
    }
    // Wrong version and kind.
    let mut v = bytes.clone();
    v[8] = 99;
    assert!(matches!(
        load_and_restore(&v),
        Err(SnapshotError::UnsupportedVersion { found: 99, .. })
    ));
    let mut v = bytes.clone();
    v[12] = 0;
    assert!(matches!(
        load_and_restore(&v),
        Err(SnapshotError::WrongKind { .. })
    ));
    assert!(matches!(
        StickSlipSnapshot::load(bytes.as_slice()),
        Err(SnapshotError::WrongKind { .. })
    ));
    // Trailing bytes.
    let mut v = bytes.clone();
    v.push(0);
    assert!(load_and_restore(&v).is_err());
    // Every truncation is an error.
    let cuts = 300;
    for i in 0..cuts {
        let len = (bytes.len() - 1) * i / cuts;
        assert!(
            load_and_restore(&bytes[..len]).is_err(),
            "truncated to {len} of {} bytes",
            bytes.len()
        );
    }
    // Mutations: an error, or a snapshot that passed every check; never a panic.
    let (mut errors, mut accepted) = (0, 0);
    for _ in 0..600 {
        let mut v = bytes.clone();
        let flips = 1 + rng.next() % 4;
        for _ in 0..flips {
            let at = 13 + (rng.next() as usize) % (v.len() - 13);
            v[at] ^= 1 << (rng.next() % 8);
        }
        match load_and_restore(&v) {
            Ok(_) => accepted += 1,
            Err(_) => errors += 1,
        }
    }
    eprintln!("mutated snapshots: {errors} rejected, {accepted} accepted (a flipped value)");
    assert!(errors > 0);
}

/// An edit of a snapshot's JSON form.
type Edit = Box<dyn FnOnce(&mut serde_json::Value)>;

/// The modifier's snapshot as JSON, edited by `edit`, and restored against `colliders`.
fn restore_edited(
    snapshot: &StickSlipSnapshot,
    colliders: &ColliderSet,
    edit: impl FnOnce(&mut serde_json::Value),
) -> Result<StickSlip<()>, String> {
    let mut json = serde_json::to_value(snapshot).unwrap();
    edit(&mut json);
    let snap: StickSlipSnapshot =
        serde_json::from_value(json).map_err(|e| format!("decode: {e}"))?;
    StickSlip::restore(&snap, colliders, ()).map_err(|e| e.to_string())
}

#[test]
fn inconsistent_snapshot_data_is_rejected() {
    let (_, snap, world) = busy_snapshot();
    let cs = &world.colliders;
    // The unedited snapshot restores through JSON as well.
    restore_edited(&snap, cs, |_| {}).unwrap();
    let json = serde_json::to_value(&snap).unwrap();
    let slots = json["contacts"]["slots"].as_array().unwrap();
    let free_slot = slots.iter().position(|s| s["record"].is_null());
    let free_slot = free_slot.expect("the busy snapshot has free slots");
    let (live_slot, live) = slots
        .iter()
        .enumerate()
        .find(|(_, s)| !s["record"].is_null())
        .unwrap();
    let handle = |i: &serde_json::Value| serde_json::json!({"index": i, "generation": 0});
    // A key-map entry for the live record's pair.
    let key = serde_json::json!({
        "c1": handle(&live["record"]["c1"]),
        "c2": handle(&live["record"]["c2"]),
        "part": {"Subshapes": [3, 4]},
        "slot": live_slot,
    });
    let push_key = move |edit: fn(&mut serde_json::Value)| -> Edit {
        let mut k = key.clone();
        edit(&mut k);
        Box::new(move |j| j["contacts"]["keys"].as_array_mut().unwrap().push(k))
    };
    // The entry itself is consistent.
    restore_edited(&snap, cs, push_key(|_| {})).unwrap();
    let cases: Vec<(&str, Edit)> = vec![
        (
            "contact store",
            push_key(|k| k["slot"] = 4_000_000_000u32.into()),
        ),
        (
            "contact store",
            Box::new(move |j| {
                j["contacts"]["keys"]
                    .as_array_mut()
                    .unwrap()
                    .push(serde_json::json!({
                        "c1": {"index": 0, "generation": 0},
                        "c2": {"index": 1, "generation": 0},
                        "part": "Whole",
                        "slot": free_slot,
                    }));
            }),
        ),
        (
            "contact store",
            push_key(|k| k["c1"]["index"] = (k["c1"]["index"].as_u64().unwrap() + 1).into()),
        ),
        (
            "contact store",
            Box::new({
                let twice = push_key(|_| {});
                let again = push_key(|k| k["part"] = serde_json::json!({"Cluster": [0, 50, 0]}));
                move |j| {
                    twice(j);
                    again(j);
                }
            }),
        ),
        (
            "contact state",
            Box::new(|j| {
                let slots = j["contacts"]["slots"].as_array_mut().unwrap();
                let live = slots.iter_mut().find(|s| !s["record"].is_null()).unwrap();
                live["record"]["force"][0] = 1e39.into(); // f32 infinity
            }),
        ),
        (
            "contact state",
            Box::new(|j| {
                let slots = j["contacts"]["slots"].as_array_mut().unwrap();
                let live = slots.iter_mut().find(|s| !s["record"].is_null()).unwrap();
                live["record"]["regime"] = 7.into();
            }),
        ),
        (
            "stiffness_time",
            Box::new(|j| j["config"]["stiffness_time"] = (-1.0).into()),
        ),
        (
            "frequency",
            Box::new(|j| j["vibrations"][0]["value"]["frequency"] = (-1.0).into()),
        ),
        (
            "decode",
            Box::new(|j| j["default_material"]["law"]["mu_ba"] = (-0.5).into()),
        ),
        (
            "normalized",
            Box::new(|j| {
                j["vibrations"][1]["value"]["waveform"]["normalized-table"][0] = 5.0.into()
            }),
        ),
        ("clock", Box::new(|j| j["clock"]["dt"] = (-1.0).into())),
        (
            "order",
            Box::new(|j| {
                let v = j["materials"].as_array_mut().unwrap();
                let e = v[0].clone();
                v.push(e);
            }),
        ),
    ];
    for (what, edit) in cases {
        let err = restore_edited(&snap, cs, edit)
            .err()
            .unwrap_or_else(|| panic!("accepted an edit of {what}"));
        assert!(err.contains(what), "{what}: {err}");
    }
    // A handle whose index no collider set holds allocates nothing and is dropped.
    let m = restore_edited(&snap, cs, |j| {
        j["materials"][0]["collider"]["index"] = (u32::MAX - 1).into();
        j["vibrations"][1]["collider"]["index"] = (u32::MAX - 1).into();
    })
    .unwrap();
    assert!(
        m.vibration(ColliderHandle::from_raw_parts(u32::MAX - 1, 0))
            .is_none()
    );
}

#[test]
fn closure_waveforms_snapshot_in_memory_but_not_to_a_file() {
    let mut s = scene();
    let mut m = modifier(Kind::Ep, VibrationMode::TimeResolved, &mut s);
    let w = Waveform::from_fn(|x| (std::f64::consts::TAU * x).sin().powi(3)).unwrap();
    let src = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.3),
        2.0,
        w,
        0.0,
        VibrationMode::TimeResolved,
    )
    .unwrap();
    m.set_vibration(s.ground, src);
    for k in 0..30 {
        step(&mut s.world, &s.bodies, &mut m, k);
    }
    let snap = m.snapshot();
    let restored = StickSlip::restore(&snap, &s.world.colliders, *m.inner()).unwrap();
    assert_eq!(
        restored.vibration(s.ground).unwrap().signal(0.37).to_bits(),
        m.vibration(s.ground).unwrap().signal(0.37).to_bits()
    );
    let err = WorldSnapshot::save_from(&s.world, &m, Vec::new()).unwrap_err();
    assert!(matches!(err, SnapshotError::Encode(_)), "{err}");
}

#[test]
fn quiet_recycled_contacts_resume_bit_identically() {
    // Boxes resting on an attached ground with nothing driving them: stickslip turns its hook
    // flag off on their colliders (rapier recycles their contacts). Saved in that state, the
    // world resumes bit for bit, also when a box is pushed awake and the pushes end.
    let build = || {
        let mut world = PhysicsWorld::default();
        let ground = world.insert_collider(cuboid3(20.0, 0.1, 20.0).0, None);
        let mut bodies = Vec::new();
        let mut colliders = vec![ground];
        for i in 0..5 {
            let (b, c) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(v3(-4.0 + 2.0 * i as f32, 0.1 + 0.25 + 0.01, 0.0))
                    .can_sleep(false),
                cuboid3(0.25, 0.25, 0.25).0.density(800.0),
            );
            bodies.push(b);
            colliders.push(c);
        }
        // A second layer on the middle box.
        let (b, c) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(0.0, 0.85 + 0.02, 0.0))
                .can_sleep(false),
            cuboid3(0.2, 0.2, 0.2).0.density(800.0),
        );
        bodies.push(b);
        colliders.push(c);
        let mut m = StickSlip::new(FrictionMaterial::new(law(Kind::Ep)))
            .with_read_back(stickslip_rapier::ReadBack::Contacts);
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
            out.extend(body_bits(&w.bodies[*b]).into_iter().map(u64::from));
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
                b.add_force(v3(f, 0.0, 0.0), true);
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

/// Hundreds of contacts, so that with rapier's `parallel` feature the hook runs on several
/// threads (rapier hands pairs to its workers in blocks of 64) and new contacts take their
/// slots in whatever order the threads reach them: the resumed run must still be identical.
#[test]
fn hundreds_of_contacts_resume_bit_identically() {
    const ROWS: usize = 14;
    // A 14 × 14 grid on the ground; in 2D, the grid's rows in one row on a longer ground.
    #[cfg(not(dim2))]
    let (at, ground_half) = (
        |x: f32, z: f32| v3(-3.6 + 0.55 * x, 0.26 + 0.02 * z, -3.6 + 0.55 * z),
        4.0,
    );
    #[cfg(dim2)]
    let (at, ground_half) = (
        |x: f32, z: f32| v3(-53.9 + 0.55 * (x + ROWS as f32 * z), 0.16, 0.0),
        55.0,
    );
    let build = || {
        let mut world = PhysicsWorld::default();
        let ground = world.insert_collider(cuboid3(ground_half, 0.1, 4.0).0, None);
        let floor = world.insert_collider(
            cuboid3(60.0, 0.1, 60.0).0.translation(v3(0.0, -3.0, 0.0)),
            None,
        );
        let mut bodies = Vec::new();
        for i in 0..ROWS * ROWS {
            let (x, z) = ((i % ROWS) as f32, (i / ROWS) as f32);
            let (b, _) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(at(x, z))
                    .can_sleep(i % 5 == 0),
                cuboid3(0.15, 0.15, 0.15).0.density(800.0),
            );
            bodies.push(b);
        }
        (world, ground, floor, bodies)
    };
    let (mut world, ground, floor, bodies) = build();
    let threads = ThreadsSeen::default();
    // The user's hook runs where the user flags it.
    for h in [ground, floor] {
        world.colliders[h].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    }
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(law(Kind::Ep)), threads.clone())
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    m.attach(&mut world.colliders, ground, None);
    m.attach(&mut world.colliders, floor, None);
    let source = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.3),
        3.0,
        Waveform::SawtoothRight,
        0.0,
        VibrationMode::TimeResolved,
    )
    .unwrap();
    m.set_vibration(ground, source);
    let push = |world: &mut PhysicsWorld, k: usize| {
        for (i, b) in bodies.iter().enumerate() {
            let body = &mut world.bodies[*b];
            let mass = body.mass();
            let phase = k as f32 * 0.03 + i as f32 * 0.37;
            // Drifting outward (edge boxes slide off), with hops.
            let out = if i % ROWS < ROWS / 2 { -0.12 } else { 0.12 };
            let fx = mass * 9.81 * (out + 0.52 * phase.sin());
            let lift = if (k + 7 * i) % 250 < 10 { 14.0 } else { 0.0 };
            body.reset_forces(false);
            body.add_force(v3(fx, mass * lift, 0.3 * fx), true);
        }
    };
    let bits = |world: &PhysicsWorld, m: &StickSlip<ThreadsSeen>| {
        let mut out = Vec::new();
        for b in &bodies {
            out.extend(body_bits(&world.bodies[*b]).into_iter().map(u64::from));
        }
        for r in m.reports().unwrap() {
            out.extend(report_bits(r));
        }
        out.extend(totals_bits(&m.totals().unwrap()));
        out
    };
    for k in 0..200 {
        push(&mut world, k);
        m.step(&mut world);
    }
    let at_snapshot = m.active_contacts();
    assert!(at_snapshot >= 150, "{at_snapshot} contacts");
    let mut bytes = Vec::new();
    WorldSnapshot::save_from(&world, &m, &mut bytes).unwrap();
    let (mut w2, mut m2) = WorldSnapshot::load(bytes.as_slice())
        .unwrap()
        .restore(threads.clone())
        .unwrap();
    let capacity = m.state_capacity();
    let pairs = |m: &StickSlip<ThreadsSeen>| {
        m.reports()
            .unwrap()
            .iter()
            .map(|r| (r.collider1, r.collider2))
            .collect::<std::collections::HashSet<_>>()
    };
    let before = pairs(&m);
    let mut new_pairs = std::collections::HashSet::new();
    let (mut lo, mut hi) = (usize::MAX, 0);
    for k in 200..200 + AFTER {
        push(&mut world, k);
        push(&mut w2, k);
        m.step(&mut world);
        m2.step(&mut w2);
        assert!(bits(&world, &m) == bits(&w2, &m2), "differs at step {k}");
        lo = lo.min(m.reports().unwrap().len());
        hi = hi.max(m.reports().unwrap().len());
        new_pairs.extend(pairs(&m).difference(&before).copied());
    }
    // Contacts come and go after the restore, and pairs the snapshot never saw take state.
    assert!(
        lo < hi && !new_pairs.is_empty(),
        "{lo}..{hi}, {} new",
        new_pairs.len()
    );
    let n_threads = threads.0.lock().unwrap().len();
    eprintln!(
        "{at_snapshot} contacts at the snapshot ({} bytes), {lo}..{hi} reported after, \
         {} new pairs, slots {capacity} -> {}, hook ran on {n_threads} thread(s): identical over {AFTER} steps",
        bytes.len(),
        new_pairs.len(),
        m.state_capacity()
    );
    #[cfg(feature = "parallel")]
    assert!(n_threads >= 2, "the hook ran on {n_threads} thread(s)");
}

/// Inner hooks recording the threads the contact hook runs on.
#[derive(Clone, Default)]
struct ThreadsSeen(
    std::sync::Arc<std::sync::Mutex<std::collections::HashSet<std::thread::ThreadId>>>,
);

impl PhysicsHooks for ThreadsSeen {
    fn modify_solver_contacts(&self, _: &mut ContactModificationContext) {
        if let Ok(mut seen) = self.0.lock() {
            seen.insert(std::thread::current().id());
        }
    }
}

/// Balls with rolling (and, in 3D, spinning) resistance on an attached ground (a law whose
/// rolling level falls with speed below its break-away): rolled at
/// different speeds and spun, they roll, slow down and come to hold; one rolls off the
/// ground's edge (its pair and joint go). Saved while they roll, the world resumes bit for
/// bit: the resisting joints of the saved world are kept with their states. Restored without
/// those states (as a file of an earlier build is), the run diverges: they matter.
#[test]
fn rolling_and_spinning_resistance_resumes_bit_identically() {
    // A Stribeck-like resistance: break-away 0.05, rolling at 0.06 falling to 0.03 with the
    // rolling speed (a fresh state holds at its capacity, where a rolling one is at 0.03).
    let curve = Curve::stribeck(0.06, 0.03, 0.05, StribeckDecay::Exponential, 0.01).unwrap();
    let resist = Law::elasto_plastic(1e4, 0.05, 0.06, curve).unwrap();
    let build = || {
        let mut world = PhysicsWorld::default();
        let ground = world.insert_collider(cuboid3(4.0, 0.1, 4.0).0, None);
        let mut bodies = Vec::new();
        let mut colliders = vec![ground];
        let r = 0.1f32;
        for (i, v) in [0.2f32, 0.5, 0.9, 4.0].into_iter().enumerate() {
            let (b, c) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(v3(1.0 + 0.2 * i as f32, 0.1 + r, -1.0 + 0.6 * i as f32))
                    .linvel(v3(v, 0.0, 0.0))
                    .can_sleep(false),
                ColliderBuilder::ball(r).density(1000.0),
            );
            // Rolling without slipping along +x (and, in 3D, a spin about the normal).
            #[cfg(not(dim2))]
            world.bodies[b].set_angvel(Vector::new(0.0, 3.0 * i as f32, -v / r), true);
            #[cfg(dim2)]
            world.bodies[b].set_angvel(-v / r, true);
            bodies.push(b);
            colliders.push(c);
        }
        let material = FrictionMaterial::new(law(Kind::Ep))
            .with_rolling(resist.clone())
            .with_spinning(resist.clone());
        let mut m = StickSlip::new(material).with_read_back(stickslip_rapier::ReadBack::Contacts);
        for h in &colliders {
            m.attach(&mut world.colliders, *h, None);
        }
        (world, bodies, m)
    };
    let (mut world, bodies, mut m) = build();
    for _ in 0..30 {
        m.step(&mut world);
    }
    let joints = world.impulse_joints.iter().count();
    assert_eq!(
        joints, 4,
        "every ball resists through its joint at the snapshot"
    );
    let bytes = {
        let mut b = Vec::new();
        WorldSnapshot::save_from(&world, &m, &mut b).unwrap();
        b
    };
    let (mut w2, mut m2) = WorldSnapshot::load(bytes.as_slice())
        .unwrap()
        .restore(())
        .unwrap();
    // The same world, its modifier restored without the rolling states (as a file of a
    // build that did not keep them: no `rolling` at all).
    let (mut w3, mut m3) = {
        let snap = WorldSnapshot::load(bytes.as_slice()).unwrap();
        let m3 = restore_edited(&snap.friction, &snap.world.colliders, |json| {
            json.as_object_mut().unwrap().remove("rolling");
        })
        .unwrap();
        (snap.world, m3)
    };
    // Inconsistent rolling states are errors.
    {
        let snap = WorldSnapshot::load(bytes.as_slice()).unwrap();
        let edits: [(&str, Edit); 4] = [
            (
                "a pair seen after the resistance's last step",
                Box::new(|j| {
                    let step = j["rolling"]["step"].as_u64().unwrap();
                    j["rolling"]["pairs"][0]["seen"] = (step + 1).into();
                }),
            ),
            (
                "pairs not in increasing collider order",
                Box::new(|j| {
                    let pairs = j["rolling"]["pairs"].as_array_mut().unwrap();
                    let first = pairs[0].clone();
                    pairs.push(first);
                }),
            ),
            (
                "unknown regime code",
                Box::new(|j| j["rolling"]["pairs"][1]["roll"]["regime"] = 9.into()),
            ),
            (
                "negative friction limit",
                Box::new(|j| j["rolling"]["pairs"][2]["spin"]["limit"] = (-1.0).into()),
            ),
        ];
        for (why, edit) in edits {
            let err = restore_edited(&snap.friction, &snap.world.colliders, edit)
                .err()
                .unwrap_or_else(|| panic!("restored with {why}"));
            assert!(err.contains(why), "{why}: {err}");
        }
    }
    let bits = |w: &PhysicsWorld, m: &StickSlip| {
        let mut out: Vec<u64> = Vec::new();
        for b in &bodies {
            out.extend(body_bits(&w.bodies[*b]).into_iter().map(u64::from));
        }
        for r in m.reports().unwrap() {
            out.extend(report_bits(r));
        }
        for r in m.rolling_reports(&w.impulse_joints) {
            out.extend(
                r.point
                    .iter()
                    .chain(&r.normal)
                    .map(|x| u64::from(x.to_bits())),
            );
            out.extend(
                r.rolling_torque
                    .iter()
                    .chain(&r.spinning_torque)
                    .chain(&[r.rolling_arm, r.spinning_arm])
                    .map(|x| u64::from(x.to_bits())),
            );
            out.extend([r.normal_force, r.rolling_limit, r.spinning_limit].map(f64::to_bits));
            out.push(format!("{:?}{:?}", r.rolling, r.spinning).len() as u64);
        }
        out
    };
    // The reports of the step before the snapshot, read from the restored world.
    assert!(
        bits(&world, &m) == bits(&w2, &m2),
        "restored reports differ"
    );
    let mut diverged = None;
    let mut joints_seen = Vec::new();
    for k in 0..600 {
        for (w, m) in [(&mut world, &mut m), (&mut w2, &mut m2), (&mut w3, &mut m3)] {
            m.step(w);
        }
        joints_seen.push(world.impulse_joints.iter().count());
        assert!(
            bits(&world, &m) == bits(&w2, &m2),
            "the rolling world resumed differently at step {k}"
        );
        if diverged.is_none() && bits(&world, &m) != bits(&w3, &m3) {
            diverged = Some(k);
        }
    }
    // The fast ball left the ground: its joint went; the others hold.
    assert_eq!(world.impulse_joints.iter().count(), 3);
    let slowest = world.bodies[bodies[0]].linvel().length();
    assert!(
        slowest < 1e-3,
        "the slowest ball still rolls at {slowest} m/s"
    );
    println!(
        "identical over 600 steps; joints {:?}..{:?}; without the states diverged at step {diverged:?}",
        joints_seen.first(),
        joints_seen.last()
    );
    assert!(
        diverged.is_some(),
        "restored without its rolling states, the run did not diverge"
    );
}
