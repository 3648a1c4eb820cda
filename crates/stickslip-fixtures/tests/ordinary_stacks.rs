//! Stacks with stickslip attached to every collider (default configuration), beside plain
//! rapier in the same test. Invariant: a pyramid of boxes, a brick wall, a crossed plank
//! tower and a 444-plank tower in the layout of rapier's `keva3` example, upright and on a
//! floor tilted to tan θ = 0.1 (μ 0.5, far below sliding), stand at least as still as under
//! plain rapier — over 10 s after settling, no more bodies moved by more than 1 mm or 1 cm
//! (keva: 2 more at most) and no more mean creep than plain rapier's (with a floor of 1 body
//! and 0.1 mm for rounding), the keva tower with at least 90 % of its colliders recycled
//! under the elasto-plastic laws (as plain rapier recycles a tower at rest) — for every law that sticks (EP, Phys, Coulomb; Regul creeps by design), and for EP with static above kinetic
//! friction (μ_ba 0.5, μ_k 0.3). A row of dominoes all falls, as in plain rapier; a box spun
//! about the normal stops at the rate twist friction gives under plain rapier, within 5 %.
//! While the keva tower settles (from 2 s, over 10 s) its motion is chaotic, so it is judged
//! across floors tilted to 0.02–0.08: summed over them, no more planks move by 1 mm under EP
//! than under plain rapier; and, with 8 solver iterations (rapier's default 4 under-converge
//! a tower whose contacts are recomputed at every step, as any hooked pair's are), on floors
//! tilted to 0.1 and 0.12 no more planks (+2) and a mean drift within 0.1 mm of plain
//! rapier's.
//! In 2D (stickslip-fixtures2d) the same for what a plane has: the pyramid, the wall and the
//! dominoes.

mod ordinary;

use ordinary::{Friction, Run, all_laws, ep};
#[cfg(not(dim2))]
use stickslip_fixtures::ordinary::spinning_box;
use stickslip_fixtures::ordinary::{Stack, dominoes, stack};
use stickslip_rapier::rapier::prelude::*;

const DT: f64 = 1.0 / 60.0;

#[derive(Debug, Clone, Copy)]
struct Stillness {
    over_1mm: usize,
    over_1cm: usize,
    /// Mean displacement along +x (downhill), m.
    creep: f64,
}

/// How long a stack settles before its stillness is measured (s): the keva tower rocks, under
/// plain rapier too, until about 4.5 s (its planks' motion, per half second, falls to none by
/// then), the smaller stacks within 2 s.
fn settling(kind: Stack) -> f64 {
    if is_keva(kind) { 6.0 } else { 2.0 }
}

/// Whether `kind` is the keva tower (3D only).
fn is_keva(kind: Stack) -> bool {
    #[cfg(not(dim2))]
    let keva = kind == Stack::Keva;
    #[cfg(dim2)]
    let keva = {
        let _ = kind;
        false
    };
    keva
}

/// How still the stack stands between `from` and `to`.
fn between(from: &[Vector], to: &[Vector]) -> Stillness {
    let moved: Vec<f32> = from
        .iter()
        .zip(to)
        .map(|(a, b)| (*b - *a).length())
        .collect();
    Stillness {
        over_1mm: moved.iter().filter(|d| **d > 1e-3).count(),
        over_1cm: moved.iter().filter(|d| **d > 1e-2).count(),
        creep: from
            .iter()
            .zip(to)
            .map(|(a, b)| (b.x - a.x) as f64)
            .sum::<f64>()
            / from.len() as f64,
    }
}

/// The stack's stillness over 10 s after [`settling`]; over 10 s after 2 s (still settling,
/// for the keva tower); and the share of colliders whose contacts are recycled at the end.
fn stillness(
    kind: Stack,
    size: usize,
    tan_theta: f64,
    friction: &Friction,
) -> (Stillness, Stillness, Option<f64>) {
    let mut run = Run::new(stack(kind, size, tan_theta, 0.5, DT), friction);
    let settle = settling(kind);
    run.run_for(2.0);
    let at_2 = run.scene.positions();
    run.run_for(settle - 2.0);
    let before = run.scene.positions();
    run.run_for(12.0 - settle);
    let at_12 = run.scene.positions();
    run.run_for(settle - 2.0);
    let after = run.scene.positions();
    let recycled = run.modifier.as_ref().map(|m| {
        let all = run.scene.all_colliders();
        all.iter().filter(|c| m.is_recycled(**c)).count() as f64 / all.len() as f64
    });
    (between(&before, &after), between(&at_2, &at_12), recycled)
}

fn stands(kind: Stack, size: usize) {
    let mut failures = Vec::new();
    for tan_theta in [0.0, 0.1] {
        let (plain, plain_early, _) = stillness(kind, size, tan_theta, &Friction::Plain);
        println!(
            "{kind:?} ({size}) tan θ {tan_theta}: plain > 1 mm {}, > 1 cm {}, creep {:.2e} m",
            plain.over_1mm, plain.over_1cm, plain.creep
        );
        if is_keva(kind) {
            println!(
                "    from 2 s, still settling: plain > 1 mm {}, creep {:.2e} m",
                plain_early.over_1mm, plain_early.creep
            );
            // What any hook gets while the tower settles: every pair of a hooked collider is
            // updated in full at every step (rapier recycles no hooked pair). Printed beside
            // the laws' windows: they lie between the two baselines or beyond.
            let (_, hooked_early, _) = stillness(kind, size, tan_theta, &Friction::Hooked);
            println!(
                "    from 2 s, still settling: no-op hook > 1 mm {}, creep {:.2e} m",
                hooked_early.over_1mm, hooked_early.creep
            );
        }
        let mut laws = all_laws(0.5);
        // Regul has no sticking: it creeps at ġ_t0 r⁻¹(|μ|/μ_ve) under any load by design
        // (crates/stickslip-fixtures/tests/rapier_incline.rs checks that speed), also under the small loads of an
        // upright stack, so a stack creeps under it (0.1–0.5 mm in 10 s here).
        laws.retain(|f| f.name() != "regul");
        laws.push(Friction::Law("ep 0.5/0.3", ep(0.5, 0.3)));
        for f in laws {
            let (s, early, recycled) = stillness(kind, size, tan_theta, &f);
            println!(
                "    {:10} > 1 mm {}, > 1 cm {}, creep {:.2e} m; recycled {:.0} %",
                f.name(),
                s.over_1mm,
                s.over_1cm,
                s.creep,
                100.0 * recycled.unwrap_or(0.0)
            );
            if is_keva(kind) {
                println!(
                    "    {:10} from 2 s, still settling: > 1 mm {}, creep {:.2e} m",
                    f.name(),
                    early.over_1mm,
                    early.creep
                );
            }
            // Bodies that may move beyond plain rapier's count (rounding).
            let allowed = |plain: usize| {
                if is_keva(kind) {
                    plain + 2
                } else {
                    plain.max(1)
                }
            };
            if s.over_1mm > allowed(plain.over_1mm)
                || s.over_1cm > allowed(plain.over_1cm)
                || s.creep.abs() > plain.creep.abs().max(1e-4)
            {
                failures.push(format!("{} at tan θ {tan_theta}: {s:?}", f.name()));
            }
            // A tower at rest recycles as under plain rapier: an elasto-plastic law's
            // contacts, loaded or touching without load, all hold.
            if is_keva(kind) && f.name().starts_with("ep") && recycled.is_some_and(|r| r < 0.9) {
                failures.push(format!(
                    "{} at tan θ {tan_theta}: recycled {recycled:?}",
                    f.name()
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{kind:?} moved: {failures:?}");
}

#[test]
fn a_pyramid_stands() {
    stands(Stack::Pyramid, 8);
}

#[test]
fn a_brick_wall_stands() {
    stands(Stack::Wall, 8);
}

#[cfg(not(dim2))]
#[test]
fn a_plank_tower_stands() {
    stands(Stack::Tower, 12);
}

#[cfg(not(dim2))]
#[test]
fn a_keva_tower_stands() {
    stands(Stack::Keva, 3);
}

/// The keva tower while it settles (from 2 s, over 10 s), on floors tilted from 0 to 0.08:
/// how many planks moved by more than 1 mm, with plain rapier's friction and with the
/// elasto-plastic law, per tilt.
#[cfg(not(dim2))]
fn keva_settling_across_tilts() -> Vec<(f64, usize, usize)> {
    let window = |tan_theta: f64, friction: &Friction| {
        let mut run = Run::new(stack(Stack::Keva, 3, tan_theta, 0.5, DT), friction);
        run.run_for(2.0);
        let from = run.scene.positions();
        run.run_for(10.0);
        between(&from, &run.scene.positions()).over_1mm
    };
    [0.02, 0.04, 0.06, 0.08]
        .into_iter()
        .map(|t| {
            (
                t,
                window(t, &Friction::Plain),
                window(t, &Friction::Law("ep", ep(0.5, 0.5))),
            )
        })
        .collect()
}

/// The settling tower's motion is chaotic: at a single tilt it can go either way (at
/// tan θ = 0.1, `a_keva_tower_stands` prints plain rapier 19 planks and EP 124; at 0.06,
/// plain 52 and EP 0). Across tilts, stickslip's tower settles no less still than plain
/// rapier's.
#[cfg(not(dim2))]
#[test]
fn a_settling_keva_tower_moves_no_more_than_under_plain_rapier_across_tilts() {
    let tilts = keva_settling_across_tilts();
    for (t, plain, ep) in &tilts {
        println!("tan θ {t}: planks > 1 mm from 2 s to 12 s: plain {plain}, EP {ep}");
    }
    // Not asserted here: near the tower's limit, at tan θ = 0.12 and rapier's default 4 solver
    // iterations, it slides down the floor under stickslip as under a hook that changes
    // nothing and as under plain rapier with contact recycling off, while plain rapier's
    // stands (see the test after this one).
    let tower = |recycling: bool| {
        let mut scene = stack(Stack::Keva, 3, 0.12, 0.5, DT);
        scene.world.integration_parameters.contact_recycling = recycling;
        scene
    };
    // What a hooked pair's full update at every step does to the warm start, counted.
    #[cfg(not(rapier_035))]
    {
        let counter = NewContacts::default();
        let mut scene = stack(Stack::Keva, 3, 0.0, 0.5, DT);
        for c in scene.all_colliders() {
            scene.world.colliders[c].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
        }
        for step in 0..720 {
            if step == 480 {
                counter.reset();
            }
            scene.world.step_with_events(&counter, &());
        }
        let (seen, new) = counter.counts();
        println!(
            "upright, 8 s to 12 s, a hook that changes nothing: {} of {} solver contacts a step \
             did not exist at the pair's last update (no warm start)",
            new / 240,
            seen / 240
        );
    }
    for (name, f, recycling) in [
        ("plain", Friction::Plain, true),
        ("plain, recycling off", Friction::Plain, false),
        ("no-op hook", Friction::Hooked, true),
        ("ep", Friction::Law("ep", ep(0.5, 0.5)), true),
    ] {
        let mut run = Run::new(tower(recycling), &f);
        let from = run.scene.positions();
        run.run_for(12.0);
        let to = run.scene.positions();
        let fallen = from
            .iter()
            .zip(&to)
            .filter(|(a, b)| (**b - **a).length() > 0.1)
            .count();
        println!(
            "tan θ 0.12, 12 s: {name}: {fallen} of {} planks moved > 10 cm, mean creep {:.3} m",
            from.len(),
            between(&from, &to).creep
        );
    }
    let (plain, ep): (usize, usize) = tilts.iter().fold((0, 0), |(p, e), t| (p + t.1, e + t.2));
    assert!(
        ep <= plain,
        "settling keva tower: EP moved {ep} planks, plain rapier {plain} ({tilts:?})"
    );
}

/// A hook that changes nothing and counts the solver contacts it sees, and those whose point
/// did not exist at the pair's last update (rapier's `NEW_CONTACT_BIT`: no warm start).
#[cfg(all(not(dim2), not(rapier_035)))]
#[derive(Default)]
struct NewContacts {
    seen: std::sync::atomic::AtomicUsize,
    new: std::sync::atomic::AtomicUsize,
}

#[cfg(all(not(dim2), not(rapier_035)))]
impl NewContacts {
    fn reset(&self) {
        self.seen.store(0, std::sync::atomic::Ordering::Relaxed);
        self.new.store(0, std::sync::atomic::Ordering::Relaxed);
    }

    fn counts(&self) -> (usize, usize) {
        let load =
            |a: &std::sync::atomic::AtomicUsize| a.load(std::sync::atomic::Ordering::Relaxed);
        (load(&self.seen), load(&self.new))
    }
}

#[cfg(all(not(dim2), not(rapier_035)))]
impl PhysicsHooks for NewContacts {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let ModifiableContacts::Rigid(m) = &ctx.contacts else {
            return;
        };
        let new = m
            .solver_contacts
            .iter()
            .filter(|c| c.contact_id[0] & NEW_CONTACT_BIT != 0)
            .count();
        let ordering = std::sync::atomic::Ordering::Relaxed;
        self.seen.fetch_add(m.solver_contacts.len(), ordering);
        self.new.fetch_add(new, ordering);
    }
}

/// Why a settling tower moves more under any contact hook than under plain rapier: rapier
/// recycles no hooked pair, it recomputes the pair's contacts at every step, and in the keva
/// tower about 1 in 6 of the points it then picks did not exist at the last update, so their
/// solve starts without warm start (the upright tower at rest under a hook that changes
/// nothing, 8 s to 12 s: the test before this one prints the count). At rapier's default 4
/// solver iterations that under-converges: tilted to 0.12 the tower slides down the floor
/// under that hook, under stickslip and under plain rapier with contact recycling off, while
/// plain rapier's stands. With 8 iterations full updates settle it, and stickslip's tower —
/// on a floor tilted to 0.1 and to 0.12, from 2 s, still settling, for 10 s — moves no more
/// planks by over 1 mm than plain rapier's (+2) and drifts within 0.1 mm of plain rapier's
/// mean drift.
#[cfg(not(dim2))]
#[test]
fn with_eight_solver_iterations_a_settling_keva_tower_moves_as_under_plain_rapier() {
    let window = |tan_theta: f64, friction: &Friction| {
        let mut scene = stack(Stack::Keva, 3, tan_theta, 0.5, DT);
        scene.world.integration_parameters.num_solver_iterations = 8;
        let mut run = Run::new(scene, friction);
        run.run_for(2.0);
        let from = run.scene.positions();
        run.run_for(10.0);
        between(&from, &run.scene.positions())
    };
    let mut failures = Vec::new();
    for tan_theta in [0.1, 0.12] {
        let plain = window(tan_theta, &Friction::Plain);
        let ep = window(tan_theta, &Friction::Law("ep", ep(0.5, 0.5)));
        println!(
            "8 iterations, tan θ {tan_theta}, from 2 s to 12 s: plain > 1 mm {}, drift {:.2e} m; \
             ep > 1 mm {}, drift {:.2e} m",
            plain.over_1mm, plain.creep, ep.over_1mm, ep.creep
        );
        if ep.over_1mm > plain.over_1mm + 2 || (ep.creep - plain.creep).abs() > 1e-4 {
            failures.push(format!("tan θ {tan_theta}: plain {plain:?}, ep {ep:?}"));
        }
    }
    assert!(failures.is_empty(), "settling keva tower: {failures:?}");
}

#[test]
fn dominoes_all_fall() {
    let count = 12;
    let fallen = |f: &Friction| {
        let mut run = Run::new(dominoes(count, 0.5, DT), f);
        run.run_for(6.0);
        // A domino has fallen once its long axis (body y) leans more than 30° from vertical.
        (0..count)
            .filter(|i| {
                run.body(*i).position().transform_vector(Vector::Y).y < 30f32.to_radians().cos()
            })
            .count()
    };
    let plain = fallen(&Friction::Plain);
    println!("dominoes fallen: plain {plain}/{count}");
    assert_eq!(
        plain, count,
        "plain rapier's row must fall for the test to mean anything"
    );
    for f in all_laws(0.5) {
        let n = fallen(&f);
        println!("    {:8} {n}/{count}", f.name());
        assert_eq!(n, count, "{}: only {n} of {count} dominoes fell", f.name());
    }
}

#[cfg(not(dim2))]
#[test]
fn a_spinning_box_stops_at_the_twist_friction_rate() {
    let spin = 10.0f32;
    // Mean deceleration of the spin over the first 0.5 s (rad/s²).
    let decel = |f: &Friction| {
        let mut run = Run::new(spinning_box(spin, 0.5, DT), f);
        run.run_for(0.5);
        (spin - run.body(0).angvel().y) as f64 / 0.5
    };
    let plain = decel(&Friction::Plain);
    println!("spin deceleration: plain {plain:.3} rad/s²");
    assert!(plain > 1.0, "plain rapier's twist friction must act");
    for f in all_laws(0.5) {
        let d = decel(&f);
        println!(
            "    {:8} {d:.3} rad/s² ({:+.2} %)",
            f.name(),
            100.0 * (d / plain - 1.0)
        );
        assert!(
            (d / plain - 1.0).abs() < 0.05,
            "{}: {d} vs {plain}",
            f.name()
        );
    }
}
