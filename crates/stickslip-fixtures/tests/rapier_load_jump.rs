//! A load that jumps in one step stays below or goes above break-away as the law says, not as
//! the solver's first pass says. Invariant: a box resting on a slope of tan 0.1 (or flat) whose
//! slope jumps in one step to a share of μ_ba below 1 holds — it moves no more than plain
//! rapier's box (whose static coefficient is μ_ba: its first solve after the jump lets the
//! contact slip a little, then it holds) plus the law's elastic range g_ba; on the heightfield,
//! where the first hooked step after recycled ones makes rapier re-pick the contact patch's
//! points (as it does every step for a pair with a hook), no more than the larger of plain
//! rapier's and rapier's own with a hook that does nothing — and above 1 it slides at the
//! closed-form kinetic acceleration g (sin θ − μ_k cos θ). Checked for EP and
//! Phys with μ_k < μ_s (a slip taken for break-away would slide the box off at μ_k), on a
//! cuboid and a heightfield ground, for masses over four decades, at 60 and 240 Hz, with
//! rapier's contact recycling on (stickslip's quiet contacts recycle) and off (every contact
//! hooked every step). In 3D and in 2D (stickslip-fixtures2d: the cuboid ground).

use stickslip_core::law::{Law, Physical};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::ordinary::{Ground, box_on_slope};
use stickslip_fixtures::v3;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

const MU_BA: f64 = 0.5;
const MU_K: f64 = 0.3;
const C: f64 = 1e5;
const G: f64 = 9.81;

fn set_slope(world: &mut PhysicsWorld, tan_theta: f64) {
    let theta = tan_theta.atan();
    world.gravity = v3((G * theta.sin()) as f32, -(G * theta.cos()) as f32, 0.0);
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Friction {
    Plain,
    /// rapier's friction with a hook that does nothing on every collider (rapier never
    /// recycles a hooked pair: every step is a full contact update).
    NoopHook,
    Ep,
    Phys,
}

struct NoopHook;

impl PhysicsHooks for NoopHook {
    fn modify_solver_contacts(&self, _: &mut ContactModificationContext) {}
}

struct Case {
    ground: Ground,
    mass: f32,
    dt: f64,
    recycling: bool,
    from: f64,
}

/// Downhill displacement (m) over 2 s after the jump to `tan_theta`, and the final
/// acceleration (m/s²).
fn after_jump(friction: Friction, case: &Case, tan_theta: f64) -> (f64, f64) {
    let dt = case.dt;
    let mut s = box_on_slope(case.ground, 0.0, MU_BA as f32, dt);
    let b = s.bodies[0];
    for h in s.world.bodies[b].colliders().to_vec() {
        s.world.colliders[h].set_density(case.mass / 0.125);
    }
    s.world.integration_parameters.contact_recycling = case.recycling;
    let law = match friction {
        Friction::Phys => {
            Law::Physical(Physical::new(MU_BA, Curve::constant(MU_K).unwrap()).unwrap())
        }
        _ => Law::elasto_plastic(C, MU_BA, MU_BA, Curve::constant(MU_K).unwrap()).unwrap(),
    };
    let mut m = StickSlip::new(FrictionMaterial::new(law));
    match friction {
        Friction::Plain => {}
        Friction::NoopHook => {
            for h in s.all_colliders() {
                let c = &mut s.world.colliders[h];
                c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
            }
        }
        Friction::Ep | Friction::Phys => {
            for h in s.all_colliders() {
                m.attach(&mut s.world.colliders, h, None);
            }
        }
    }
    let mut world = s.world;
    let mut step = |world: &mut PhysicsWorld| match friction {
        Friction::NoopHook => world.step_with_events(&NoopHook, &()),
        _ => m.step(world),
    };
    for _ in 0..(0.5 / dt) as usize {
        step(&mut world);
    }
    set_slope(&mut world, case.from);
    for _ in 0..(1.0 / dt) as usize {
        step(&mut world);
    }
    set_slope(&mut world, tan_theta);
    let x0 = world.bodies[b].translation().x as f64;
    let steps = (2.0 / dt) as usize;
    let mut v = [0.0; 2];
    for k in 0..steps {
        step(&mut world);
        if k + 2 >= steps {
            v[k + 2 - steps] = world.bodies[b].linvel().x as f64;
        }
    }
    (
        world.bodies[b].translation().x as f64 - x0,
        (v[1] - v[0]) / dt,
    )
}

fn cases() -> Vec<Case> {
    let mut out = Vec::new();
    #[cfg(not(dim2))]
    let grounds = [Ground::Cuboid, Ground::HeightField];
    #[cfg(dim2)]
    let grounds = [Ground::Cuboid];
    for ground in grounds {
        for dt in [1.0 / 60.0, 1.0 / 240.0] {
            for mass in [0.1f32, 10.0, 1000.0] {
                for recycling in [true, false] {
                    for from in [0.0, 0.1] {
                        out.push(Case {
                            ground,
                            mass,
                            dt,
                            recycling,
                            from,
                        });
                    }
                }
            }
        }
    }
    out
}

#[test]
fn a_load_jumping_below_break_away_holds() {
    let g_ba = MU_BA / C;
    let mut failures = Vec::new();
    for case in cases() {
        for share in [0.6, 0.8, 0.9, 0.95] {
            let tan = share * MU_BA;
            let (plain, _) = after_jump(Friction::Plain, &case, tan);
            let (noop, _) = after_jump(Friction::NoopHook, &case, tan);
            for friction in [Friction::Ep, Friction::Phys] {
                let (dx, _) = after_jump(friction, &case, tan);
                let rapier = if case.ground == Ground::Cuboid {
                    plain.abs()
                } else {
                    plain.abs().max(noop.abs())
                };
                let held = dx.abs() <= rapier + g_ba;
                if !held {
                    failures.push(format!(
                        "{friction:?} {:?} mass {} dt {:.4} recycling {} from {}: jump to {share} μ_ba moved {dx:.3e} m, plain rapier {plain:.3e} m, no-op hook {noop:.3e}",
                        case.ground, case.mass, case.dt, case.recycling, case.from
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_load_jumping_above_break_away_slides_at_the_kinetic_acceleration() {
    let mut failures = Vec::new();
    for case in cases() {
        for share in [1.1, 1.3] {
            let tan: f64 = share * MU_BA;
            let theta = tan.atan();
            let expected = G * (theta.sin() - MU_K * theta.cos());
            for friction in [Friction::Ep, Friction::Phys] {
                let (_, a) = after_jump(friction, &case, tan);
                let kinetic = (a / expected - 1.0).abs() < 0.02;
                if !kinetic {
                    failures.push(format!(
                        "{friction:?} {:?} mass {} dt {:.4} recycling {} from {}: jump to {share} μ_ba: a = {a:.4}, closed form {expected:.4}",
                        case.ground, case.mass, case.dt, case.recycling, case.from
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
