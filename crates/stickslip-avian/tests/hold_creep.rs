//! A contact stickslip holds in avian stays within the law's elastic range, whatever avian's
//! tick rate and substep count: a 2 kg box (0.4 m cube) with an elasto-plastic material
//! (c = 3e4 1/m, μ_ba = μ_max = 0.5, sliding at 0.4: elastic range μ_ba/c = 16.7 µm) on a floor
//! under gravity tilted to tan θ = 0.45 (0.9 of break-away) moves less than μ_ba/c over 5 s
//! and never leaves sticking: loaded at once after 0.5 s on a level floor, and put down on
//! the slope (it lands sliding, avian having no contact the tick before), at 60 and 120 Hz
//! and 2, 6 and 12 substeps. avian's own hold at μ 0.5 creeps by millimetres there (printed
//! beside). The read-back gives
//! the tick's forces over all substeps: the held box's friction m g sin θ and normal force
//! m g cos θ within 1 %, and a 3 000 kg sled dragged at 0.01 m/s, which its friction stops
//! within the first substep of every tick, a friction of m v per tick (within 1 %) where the
//! last substep carries none.

mod common;

use bevy::prelude::*;
use common::avian::prelude::*;
use common::stickslip_avian::{
    FrictionMaterial, RegimeChanged, StickSlipContacts, StickSlipFriction, core::law::Regime,
};
use common::*;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;

const MASS: f32 = 2.0;
const TAN: f64 = 0.45;
const C: f64 = 3e4;
const MU_BA: f64 = 0.5;

/// Regime changes of the run.
#[derive(Resource, Default)]
struct Seen(Vec<RegimeChanged>);

fn record(mut messages: MessageReader<RegimeChanged>, mut seen: ResMut<Seen>) {
    seen.0.extend(messages.read().copied());
}

/// The held box's displacement over 5 s from 0.5 s after it is loaded, the regimes it went
/// through then, and the read-back's friction and normal force at the end (N); with avian's
/// own friction at μ_ba unless `stickslip`. Put down on the slope, or with `level_first` on a
/// level floor for 0.5 s before the slope comes at once (a load jump).
fn hold_from(
    stickslip: bool,
    hz: f64,
    substeps: u32,
    level_first: bool,
) -> (Vec3, Vec<Regime>, f64, f64) {
    let start = if level_first { 0.0 } else { TAN.atan() };
    let mut app = app_at(stickslip, hz, substeps, tilted_gravity(start));
    if !stickslip {
        app.add_message::<RegimeChanged>();
    }
    app.init_resource::<Seen>().add_systems(PostUpdate, record);
    let ep = Law::elasto_plastic(C, MU_BA, MU_BA, Curve::constant(0.4).unwrap()).unwrap();
    let material = (
        StickSlipFriction(Some(FrictionMaterial::new(ep))),
        Friction::new(MU_BA as f32),
    );
    floor(&mut app, material.clone());
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid_collider(0.4, 0.4, 0.4),
            Mass(MASS),
            Transform::from_xyz(0.0, 0.2, 0.0),
            SleepingDisabled,
            material,
        ))
        .id();
    let ticks = |s: f64| (s * hz).round() as usize;
    run(&mut app, ticks(0.5));
    if level_first {
        tilt(&mut app, TAN.atan());
        run(&mut app, ticks(0.5));
    }
    let p0 = position(&app, b);
    app.world_mut().resource_mut::<Seen>().0.clear();
    run(&mut app, ticks(5.0));
    let moved = position(&app, b) - p0;
    let regimes = app
        .world()
        .resource::<Seen>()
        .0
        .iter()
        .map(|m| m.to)
        .collect();
    let contacts = app
        .world()
        .get_resource::<StickSlipContacts>()
        .map_or(&[][..], |c| &c.0);
    let friction: Vec3 = contacts.iter().map(|c| Vec3::from(c.friction_force)).sum();
    let normal: f64 = contacts.iter().map(|c| c.normal_force).sum();
    (moved, regimes, friction.length() as f64, normal)
}

/// Checks one hold: within the elastic range, sticking throughout, and the read-back's forces.
fn check(hz: f64, substeps: u32, level_first: bool) {
    let range = MU_BA / C;
    let weight = MASS as f64 * G;
    let theta = TAN.atan();
    let (moved, regimes, friction, normal) = hold_from(true, hz, substeps, level_first);
    let (avian, ..) = hold_from(false, hz, substeps, level_first);
    let what = format!(
        "{hz} Hz, {substeps} substeps, {}",
        if level_first {
            "slope after 0.5 s level"
        } else {
            "put down on the slope"
        }
    );
    println!(
        "{what}: stickslip moved {:.2} µm, avian alone at μ {MU_BA} {:.1} µm",
        moved.length() * 1e6,
        avian.length() * 1e6
    );
    assert!(
        (moved.length() as f64) < range,
        "{what}: moved {moved:?} m (range {range} m)"
    );
    assert!(
        regimes.iter().all(|r| *r == Regime::Sticking),
        "{what}: {regimes:?}"
    );
    let (f_t, f_n) = (weight * theta.sin(), weight * theta.cos());
    assert!(
        (friction - f_t).abs() < 0.01 * f_t,
        "{what}: friction {friction} N, m g sin θ {f_t} N"
    );
    assert!(
        (normal - f_n).abs() < 0.01 * f_n,
        "{what}: normal force {normal} N, m g cos θ {f_n} N"
    );
}

#[test]
fn a_box_loaded_to_0_9_of_break_away_holds_within_the_elastic_range() {
    for hz in [60.0, 120.0] {
        for substeps in [2, 6, 12] {
            check(hz, substeps, true);
        }
    }
}

#[test]
fn a_box_put_down_on_the_slope_holds_within_the_elastic_range() {
    // Put down, the box falls free for the tick before avian has its contact and lands
    // sliding; the law holds it at its capacity while that slide shrinks (avian brakes it
    // with every point at its own clamp), then holds it while avian's soft normal rows move
    // the load from the back points to the front ones.
    for hz in [60.0, 120.0] {
        for substeps in [2, 6, 12] {
            check(hz, substeps, false);
        }
    }
}

#[test]
fn the_read_back_gives_the_friction_of_the_whole_tick() {
    const SLED: f32 = 3000.0;
    const DRAG: f32 = 0.01;
    for substeps in [2, 6, 12] {
        let mut app = app_at(true, HZ, substeps, gravity(Vec3::new(0.0, -G as f32, 0.0)));
        floor(&mut app, StickSlipFriction(None));
        let sled = app
            .world_mut()
            .spawn((
                RigidBody::Dynamic,
                cuboid_collider(1.0, 0.2, 1.0),
                Mass(SLED),
                Transform::from_xyz(0.0, 0.1, 0.0),
                SleepingDisabled,
                StickSlipFriction(None),
                LockedAxes::ROTATION_LOCKED,
            ))
            .id();
        run(&mut app, 30);
        let mut reported = Vec::new();
        for _ in 0..30 {
            app.world_mut().get_mut::<LinearVelocity>(sled).unwrap().0.x = DRAG;
            app.update();
            let contacts = &app.world().resource::<StickSlipContacts>().0;
            let f: f32 = contacts.iter().map(|c| c.friction_force[0]).sum();
            reported.push(f.abs() as f64);
        }
        // The default material's limit μ m g h per substep exceeds m v: the sled stops within
        // the first substep, so the tick's friction impulse is m v.
        let expected = (SLED * DRAG) as f64 * HZ;
        for f in &reported {
            assert!(
                (f - expected).abs() < 0.01 * expected,
                "{substeps} substeps: friction {f} N, m v / dt {expected} N ({reported:?})"
            );
        }
    }
}
