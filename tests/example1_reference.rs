//! The seed's Example 1 with the reference ODE simulators: a block under F(t) in three phases.
//! Invariants: in phase I (force at 0.95 F_ba) the elasto-plastic law sticks, its displacement
//! never exceeding g_ba = μ_ba/c, while the regularized law creeps far beyond g_ba; in phases
//! II–III EP follows the exact switched model (final displacement within 1 %), with both the
//! explicit (Dormand–Prince) and the implicit (ESDIRK) integrator; the switched model
//! matches the closed-form sliding solution of a constant-force arc; and every law's output is
//! a trajectory: times never go back, the switched model never past its stop.

use stickslip::core::law::{Coulomb, Law, Physical, Regularization, Regularized};
use stickslip::core::sliding_curve::Curve;
use stickslip_theory::block::{Block, ForceProfile, Integrator, Tolerances, simulate};

const M: f64 = 1.0;
const G: f64 = 9.81;
const MU_BA: f64 = 0.3;
const MU_MAX: f64 = 0.32;
const C: f64 = 1e4;

fn curve() -> Curve {
    Curve::constant(MU_MAX).unwrap()
}

fn profile() -> ForceProfile {
    ForceProfile::example1(MU_BA * M * G, 0.95, 1.5).unwrap()
}

fn run(law: Law, integrator: Integrator) -> stickslip_theory::block::BlockRun {
    let block = Block::new(M, G, law).unwrap();
    simulate(
        &block,
        &profile(),
        integrator,
        Tolerances::default(),
        &[1.0, 2.0, 3.0],
    )
    .unwrap()
}

#[test]
fn ep_sticks_in_phase_one_and_regul_creeps() {
    let g_ba = MU_BA / C;
    for integrator in [Integrator::Explicit, Integrator::Implicit] {
        let ep = run(
            Law::elasto_plastic(C, MU_BA, MU_MAX, curve()).unwrap(),
            integrator,
        );
        let max_ep = ep.max_displacement_between(0.0, 1.0);
        assert!(
            max_ep <= g_ba,
            "{integrator:?}: EP moved {max_ep} > g_ba {g_ba}"
        );
        // Quasi-static elastic displacement at 0.95 F_ba is 0.95 g_ba: the law is loaded.
        assert!(max_ep > 0.8 * g_ba, "EP spring not loaded: {max_ep}");

        let regul = run(
            Law::Regularized(Regularized::new(curve(), 0.01, Regularization::Linear).unwrap()),
            integrator,
        );
        let creep = regul.phases[0].x;
        assert!(
            creep > 50.0 * g_ba,
            "Regul should creep, moved only {creep}"
        );
    }
}

#[test]
fn ep_follows_phys_through_slip_and_back_to_rest() {
    let phys_law = Law::Physical(Physical::new(MU_BA, curve()).unwrap());
    for integrator in [Integrator::Explicit, Integrator::Implicit] {
        let phys = run(phys_law.clone(), integrator);
        let ep = run(
            Law::elasto_plastic(C, MU_BA, MU_MAX, curve()).unwrap(),
            integrator,
        );
        let (xp, xe) = (phys.final_displacement(), ep.final_displacement());
        assert!(xp > 0.1, "the block should have slid, phys moved {xp}");
        assert!(
            ((xe - xp) / xp).abs() < 0.01,
            "{integrator:?}: EP {xe} vs Phys {xp}"
        );
        // Both end at rest.
        assert!(phys.phases[2].v.abs() < 1e-9);
        assert!(
            ep.phases[2].v.abs() < 1e-2,
            "EP still moving: {}",
            ep.phases[2].v
        );
    }
}

#[test]
fn switched_model_matches_closed_form_arcs() {
    // Coulomb μ with F(t) = const above μ m g from t = 0: x(t) = ½ (F/m − μ g) t².
    let mu = 0.2;
    let f = 3.0;
    let p = ForceProfile::new(vec![0.0, 1.0], vec![f, f]).unwrap();
    let block = Block::new(M, G, Law::Coulomb(Coulomb::new(mu).unwrap())).unwrap();
    for integrator in [Integrator::Explicit, Integrator::Implicit] {
        let r = simulate(&block, &p, integrator, Tolerances::default(), &[1.0]).unwrap();
        let expect = 0.5 * (f / M - mu * G);
        assert!(
            (r.phases[0].x - expect).abs() < 1e-6 * expect,
            "{} vs {expect}",
            r.phases[0].x
        );
    }
    // Release at F = 0 after sliding: stopping distance v²/(2 μ g) after the push.
    let p = ForceProfile::new(vec![0.0, 1.0, 1.0 + 1e-9, 3.0], vec![f, f, 0.0, 0.0]).unwrap();
    let r = simulate(
        &block,
        &p,
        Integrator::Explicit,
        Tolerances::default(),
        &[3.0],
    )
    .unwrap();
    let v1 = f / M - mu * G;
    let expect = 0.5 * v1 + v1 * v1 / (2.0 * mu * G);
    assert!(
        (r.final_displacement() - expect).abs() < 1e-5,
        "{} vs {expect}",
        r.final_displacement()
    );
    assert!(r.stick_time > 1.0 && r.slip_time > 1.0);
}

#[test]
fn output_times_increase_and_the_switched_model_stays_stopped() {
    let laws = [
        Law::Physical(Physical::new(MU_BA, curve()).unwrap()),
        Law::Coulomb(Coulomb::new(MU_MAX).unwrap()),
        Law::elasto_plastic(C, MU_BA, MU_MAX, curve()).unwrap(),
        Law::Regularized(Regularized::new(curve(), 0.01, Regularization::Linear).unwrap()),
    ];
    for law in laws {
        for integrator in [Integrator::Explicit, Integrator::Implicit] {
            let r = run(law.clone(), integrator);
            assert!(
                r.t.windows(2).all(|w| w[1] >= w[0]),
                "{} {integrator:?}: output times go back",
                r.law
            );
            if matches!(law, Law::Physical(_) | Law::Coulomb(_)) {
                // After the slip-stick of phase III the block rests where it stopped.
                let x_end = r.final_displacement();
                let late = r.max_displacement_between(2.5, 3.0);
                let low =
                    r.t.iter()
                        .zip(&r.x)
                        .filter(|(t, _)| **t >= 2.5)
                        .fold(f64::INFINITY, |m, (_, x)| m.min(*x));
                assert!(
                    late - low < 1e-9 && (late - x_end).abs() < 1e-9,
                    "{} {integrator:?}: moved after stopping ({low}..{late})",
                    r.law
                );
            }
        }
    }
}
