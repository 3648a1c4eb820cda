//! A sled dragged over a plate in an avian world follows the sliding curve of its
//! elasto-plastic material. Invariant: a sled pressed onto a static plate by F = 9.81 N
//! (gravity off, rotations locked) and dragged at an imposed speed v from 1 mm/s to 1 m/s (its
//! velocity along x is set before every tick; it is heavy enough that one tick's friction
//! changes it by 1 %, so the solver applies the contact's full friction) feels, once its
//! elastic range is behind it, the friction coefficient μ_ve(v) of the law's Stribeck curve —
//! falling from μ_ve(0+) towards the Coulomb level, then rising with the viscous term — within
//! 2 %: measured from the sled's momentum (m Δv per tick over F dt, no read-back involved) and
//! from the read-back (`StickSlipContacts`), at avian's default 6 substeps and at 12. The
//! momentum measure reads plain avian's own friction exactly.

mod common;

use bevy::prelude::*;
use common::avian::prelude::*;
use common::stickslip_avian::{FrictionMaterial, StickSlipContacts, StickSlipFriction};
use common::*;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};

/// Law stiffness (1/m): elastic range μ_ba/c = 50 µm.
const C: f64 = 1e4;
/// Break-away coefficient, below the curve's value at rest.
const MU_BA: f64 = 0.5;
/// Pressing force (N).
const F: f64 = 9.81;
const DT: f64 = 1.0 / HZ;

/// μ_ve(v) = 0.3 + 0.25 e^(−v/0.02) + 0.1 v: 0.55 at rest, 0.31 near 0.1 m/s, 0.40 at 1 m/s.
fn curve() -> Curve {
    Curve::stribeck(0.55, 0.3, 0.02, StribeckDecay::Exponential, 0.1).unwrap()
}

fn law() -> Law {
    Law::elasto_plastic(C, MU_BA, curve().at_rest(), curve()).unwrap()
}

/// (μ from the sled's momentum, μ from the read-back) of the sled dragged at `v`, averaged
/// over 1 s after the contact has slid 25 elastic ranges (and at least 0.5 s); with `plain`,
/// plain avian friction of that coefficient instead (read-back NaN).
fn dragged(v: f64, substeps: u32, plain: Option<f32>) -> (f64, f64) {
    let mut app = app_at(plain.is_none(), HZ, substeps, gravity(Vec3::ZERO));
    let mu_max = curve().at_rest();
    let mass = mu_max * F * DT / (0.01 * v);
    let material = StickSlipFriction(Some(FrictionMaterial::new(law())));
    let friction = Friction::new(plain.unwrap_or(0.5));
    let plate = floor(&mut app, friction);
    let sled = sled(&mut app, mass, F, friction);
    if plain.is_none() {
        app.world_mut().entity_mut(plate).insert(material.clone());
        app.world_mut().entity_mut(sled).insert(material);
    }
    let settle = ((25.0 * MU_BA / C / v).max(0.5) / DT).ceil() as usize;
    let measure = HZ as usize;
    let (mut impulse, mut reported, mut normal) = (0.0, 0.0, 0.0);
    for k in 0..settle + measure {
        drag_tick(&mut app, sled, v);
        if k >= settle {
            impulse += mass * (v - velocity(&app, sled).x as f64);
            let Some(contacts) = app.world().get_resource::<StickSlipContacts>() else {
                continue;
            };
            for c in contacts.of(sled) {
                reported += Vec3::from(c.friction_force).length() as f64;
                normal += c.normal_force;
            }
        }
    }
    let momentum = impulse / (F * DT * measure as f64);
    let reports = if plain.is_some() {
        f64::NAN
    } else {
        reported / normal
    };
    (momentum, reports)
}

#[test]
fn the_momentum_measure_reads_plain_avians_friction() {
    for v in [1e-2, 1.0] {
        let (mu, _) = dragged(v, 6, Some(0.4));
        assert!((mu / 0.4 - 1.0).abs() < 0.005, "v {v}: {mu} vs 0.4");
    }
}

#[test]
fn a_dragged_sled_follows_the_stribeck_curve_over_three_decades() {
    let speeds = [1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0];
    let mut worst = 0.0f64;
    for substeps in [6, 12] {
        for v in speeds {
            let expected = curve().mu(v);
            let (momentum, reports) = dragged(v, substeps, None);
            let (e_m, e_r) = (momentum / expected - 1.0, reports / expected - 1.0);
            worst = worst.max(e_m.abs()).max(e_r.abs());
            println!(
                "{substeps:2} substeps v {v:7.3} m/s: μ_ve {expected:.4}, momentum {momentum:.4} \
                 ({:+.2} %), read-back {reports:.4} ({:+.2} %)",
                100.0 * e_m,
                100.0 * e_r
            );
            assert!(
                e_m.abs() < 0.02 && e_r.abs() < 0.02,
                "v {v}, {substeps} substeps: momentum {momentum}, read-back {reports}, curve {expected}"
            );
        }
    }
    println!("worst relative error {:.2} %", 100.0 * worst);
}
