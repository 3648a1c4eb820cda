//! A sled dragged over a plate in a rapier world, 3D and 2D (stickslip-fixtures2d), follows the sliding curve of its
//! elasto-plastic law. Invariant: a sled pressed onto a fixed plate by F = 9.81 N (gravity
//! off) and dragged at an imposed speed v from 1 mm/s to 1 m/s (its horizontal velocity is
//! set every step; it is heavy enough that one step's friction changes it by 1 %, so the
//! solver applies the contact's full friction) feels, once its elastic range is behind it, the
//! friction coefficient μ_ve(v) of the law's Stribeck curve — falling from μ_ve(0+) towards the
//! Coulomb level, then rising with the viscous term — within 2 %: measured from the sled's
//! momentum (m Δv per step over F dt, no read-back involved) and from the contact reports,
//! at 60 Hz and 240 Hz, whichever collider rapier lists first, with the default
//! `StickSlipConfig`, also on a plate turned off the axes (contact normals along no world
//! axis). The momentum measure reads plain rapier's own friction exactly.

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};
use stickslip_fixtures::dim::spin;
use stickslip_fixtures::{Sled, cuboid3, v3};
use stickslip_rapier::ReadBack;
use stickslip_rapier::rapier::math::rotation_from_angle;
use stickslip_rapier::rapier::prelude::*;

/// Law stiffness (1/m): elastic range μ_ba/c = 50 µm.
const C: f64 = 1e4;
/// Break-away coefficient, below the curve's value at rest (μ_max = μ_ve(0+)).
const MU_BA: f64 = 0.5;
/// Pressing force (N).
const F: f64 = 9.81;

/// μ_ve(v) = 0.3 + 0.25 e^(−v/0.02) + 0.1 v: 0.55 at rest, 0.31 near 0.1 m/s, 0.40 at 1 m/s.
fn curve() -> Curve {
    Curve::stribeck(0.55, 0.3, 0.02, StribeckDecay::Exponential, 0.1).unwrap()
}

fn law() -> Law {
    Law::elasto_plastic(C, MU_BA, curve().at_rest(), curve()).unwrap()
}

/// (μ from the sled's momentum, μ from the reports) of the sled dragged at `v` with step
/// `dt`, averaged over 1 s after the contact has slid 25 elastic ranges (and at least 0.5 s);
/// with `plain`, plain rapier friction of that coefficient instead (no reports: NaN).
fn dragged(v: f64, dt: f64, plain: Option<f32>) -> (f64, f64) {
    dragged_in_order(v, dt, plain, false)
}

/// [`dragged`], the sled inserted before the plate when `sled_first`.
fn dragged_in_order(v: f64, dt: f64, plain: Option<f32>, sled_first: bool) -> (f64, f64) {
    let mu_max = curve().at_rest();
    // One step's friction impulse is 1 % of the sled's momentum.
    let mass = mu_max * F * dt / (0.01 * v);
    let mut sled = Sled::with_order(0.1, mass as f32, dt, plain.unwrap_or(0.0), sled_first);
    let mut m = plain
        .is_none()
        .then(|| sled.attach(law()).with_read_back(ReadBack::Contacts));
    let press = v3(0.0, -(F as f32), 0.0);
    let settle = ((25.0 * MU_BA / C / v).max(0.5) / dt).ceil() as usize;
    let measure = (1.0 / dt).round() as usize;
    let mass = sled.mass();
    let (mut impulse, mut reported, mut normal) = (0.0, 0.0, 0.0);
    for k in 0..settle + measure {
        sled.drive(v);
        sled.set_force(press);
        match m.as_mut() {
            Some(m) => m.step(&mut sled.world),
            None => sled.world.step(),
        }
        if k >= settle {
            impulse += mass * (v - sled.vx());
            let Some(m) = m.as_ref() else { continue };
            let r = m.reports().unwrap();
            assert_eq!(r.len(), 1, "one contact manifold");
            assert_eq!(r[0].collider1 == sled.sled, sled_first, "the pair's order");
            // The friction on the sled: collider 2's, or the reaction on collider 1.
            let sign = if r[0].collider2 == sled.sled {
                -1.0
            } else {
                1.0
            };
            reported += sign * r[0].friction_force[0] as f64;
            normal += r[0].normal_force;
        }
    }
    let from_reports = if m.is_some() {
        reported / normal
    } else {
        f64::NAN
    };
    (impulse / (F * measure as f64 * dt), from_reports)
}

#[test]
fn the_momentum_measure_reads_plain_rapier_friction() {
    // The measurement itself, on rapier's own Coulomb friction: flat at its coefficient.
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for v in [1e-3, 0.1, 1.0] {
            let (mu, _) = dragged(v, dt, Some(0.4));
            println!("plain rapier μ 0.4 at {:.0} Hz, v {v}: {mu:.4}", 1.0 / dt);
            assert!((mu / 0.4 - 1.0).abs() < 0.005, "v {v} dt {dt}: {mu}");
        }
    }
}

#[test]
fn dragged_sled_follows_the_stribeck_curve_over_three_decades() {
    let speeds = [1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0];
    let mut worst = 0.0f64;
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for v in speeds {
            let expected = curve().mu(v);
            let (momentum, reports) = dragged(v, dt, None);
            let (e_m, e_r) = (momentum / expected - 1.0, reports / expected - 1.0);
            worst = worst.max(e_m.abs()).max(e_r.abs());
            println!(
                "{:3.0} Hz v {v:7.3} m/s: μ_ve {expected:.4}, momentum {momentum:.4} ({:+.2} %), \
                 reports {reports:.4} ({:+.2} %)",
                1.0 / dt,
                100.0 * e_m,
                100.0 * e_r
            );
            assert!(
                e_m.abs() < 0.02 && e_r.abs() < 0.02,
                "v {v} at dt {dt}: momentum {momentum}, reports {reports}, curve {expected}"
            );
        }
    }
    println!("worst relative error {:.2} %", 100.0 * worst);
}

#[test]
fn the_order_of_the_pair_changes_nothing() {
    // The sled as the pair's collider 1 (contact normal pointing down): the same friction,
    // and the reports give the force on collider 2 (the plate) with the opposite sign.
    for v in [3e-3, 0.1, 1.0] {
        let expected = curve().mu(v);
        let (momentum, reports) = dragged_in_order(v, 1.0 / 60.0, None, true);
        println!(
            "sled first, v {v}: μ_ve {expected:.4}, momentum {momentum:.4}, reports {reports:.4}"
        );
        assert!(
            (momentum / expected - 1.0).abs() < 0.02 && (reports / expected - 1.0).abs() < 0.02,
            "v {v}: {momentum} / {reports} vs {expected}"
        );
    }
}

/// μ from the momentum of a sled dragged at `v` along a plate turned by `phi` (the whole
/// scene turned: plate, sled, pressing force and drive), and from the reports.
fn dragged_on_turned_plate(v: f64, phi: f32) -> (f64, f64) {
    let dt = 1.0 / 60.0;
    let rot = rotation_from_angle(spin(phi));
    let (t, n) = (rot * v3(1.0, 0.0, 0.0), rot * v3(0.0, 1.0, 0.0));
    let half = 0.1f32;
    let mass = curve().at_rest() * F * dt / (0.01 * v);
    let mut world = PhysicsWorld {
        gravity: Vector::ZERO,
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = dt as f32;
    let plate = world.insert_collider(cuboid3(500.0, 0.1, 50.0).0.rotation(spin(phi)), None);
    let (body, sled) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(n * (0.1 + half))
            .rotation(spin(phi))
            .lock_rotations()
            .can_sleep(false),
        {
            let (cube, volume) = cuboid3(half, half, half);
            cube.density(mass as f32 / volume)
        },
    );
    let mut m = stickslip_rapier::StickSlip::new(stickslip_rapier::FrictionMaterial::new(law()))
        .with_read_back(ReadBack::Contacts);
    m.attach(&mut world.colliders, plate, None);
    m.attach(&mut world.colliders, sled, None);
    let settle = ((25.0 * MU_BA / C / v).max(0.5) / dt).ceil() as usize;
    let measure = 60;
    let (mut impulse, mut reported, mut normal) = (0.0, 0.0, 0.0);
    for k in 0..settle + measure {
        let b = &mut world.bodies[body];
        let vn = b.linvel().dot(n);
        b.set_linvel(t * v as f32 + n * vn, true);
        b.reset_forces(true);
        b.add_force(-n * F as f32, true);
        m.step(&mut world);
        if k >= settle {
            let b = &world.bodies[body];
            impulse += b.mass() as f64 * (v - b.linvel().dot(t) as f64);
            let r = m.reports().unwrap()[0];
            let on_sled = if r.collider2 == sled { -1.0 } else { 1.0 };
            let f = Vector::from_array(r.friction_force);
            reported += on_sled * f.dot(t) as f64;
            normal += r.normal_force;
            // The reported normal is the plate's, up to the pair's order.
            let rn = Vector::from_array(r.normal);
            assert!(rn.dot(n).abs() > 0.999, "normal {rn:?} vs {n:?}");
        }
    }
    (impulse / (F * measure as f64 * dt), reported / normal)
}

#[test]
fn a_turned_plate_gives_the_same_curve() {
    // Contact normals off the axes: the tangent line and the friction measured along it.
    for phi in [0.5f32, 2.0, -2.8] {
        for v in [3e-3, 0.1, 1.0] {
            let expected = curve().mu(v);
            let (momentum, reports) = dragged_on_turned_plate(v, phi);
            println!(
                "plate turned {phi} rad, v {v}: μ_ve {expected:.4}, momentum {momentum:.4}, \
                 reports {reports:.4}"
            );
            assert!(
                (momentum / expected - 1.0).abs() < 0.02 && (reports / expected - 1.0).abs() < 0.02,
                "φ {phi} v {v}: {momentum} / {reports} vs {expected}"
            );
        }
    }
}
