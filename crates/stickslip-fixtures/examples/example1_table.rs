//! The seed's Example 1 with the reference simulators: prints, for each law and integrator, the
//! displacement and velocity at the end of each phase, the stick/slip times and the integrator
//! cost (steps, right-hand-side evaluations, wall time).
//!
//! Run: `cargo run --release --example example1_table`

use stickslip_core::law::{Law, Physical, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_theory::block::{Block, ForceProfile, Integrator, Tolerances, simulate};

fn main() {
    let (m, g, mu_ba, mu_max, c) = (1.0, 9.81, 0.3, 0.32, 1e4);
    let curve = Curve::constant(mu_max).expect("valid curve");
    let profile = ForceProfile::example1(mu_ba * m * g, 0.95, 1.5).expect("valid profile");
    let laws = [
        Law::elasto_plastic(c, mu_ba, mu_max, curve.clone()).expect("valid EP"),
        Law::Physical(Physical::new(mu_ba, curve.clone()).expect("valid Phys")),
        Law::Regularized(
            Regularized::new(curve.clone(), 0.01, Regularization::Linear).expect("valid Regul"),
        ),
    ];
    println!(
        "{:<6} {:<9} {:>12} {:>12} {:>12} {:>9} {:>9} {:>9} {:>9} {:>10}",
        "law",
        "method",
        "x(1s) m",
        "x(2s) m",
        "x(3s) m",
        "v(3s)",
        "stick s",
        "steps",
        "evals",
        "time ms"
    );
    for law in &laws {
        for integrator in [Integrator::Explicit, Integrator::Implicit] {
            let block = Block::new(m, g, law.clone()).expect("valid block");
            match simulate(
                &block,
                &profile,
                integrator,
                Tolerances::default(),
                &[1.0, 2.0, 3.0],
            ) {
                Ok(r) => println!(
                    "{:<6} {:<9} {:>12.4e} {:>12.6} {:>12.6} {:>9.2e} {:>9.3} {:>9} {:>9} {:>10.2}",
                    r.law,
                    format!("{integrator:?}"),
                    r.phases[0].x,
                    r.phases[1].x,
                    r.phases[2].x,
                    r.phases[2].v,
                    r.stick_time,
                    r.stats.accepted_steps,
                    r.stats.function_evals,
                    r.stats.seconds * 1e3
                ),
                Err(e) => println!(
                    "{:<6} {:<9} failed: {e}",
                    law.as_dyn().name(),
                    format!("{integrator:?}")
                ),
            }
        }
    }
    // The same Example 1 in a rapier world with the EP contact (the reference: Phys above).
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        let law = Law::elasto_plastic(c, mu_ba, mu_max, curve.clone()).expect("valid EP");
        let (xs, v_end) = stickslip_fixtures::example1(law, &profile, dt, &[1.0, 2.0, 3.0]);
        println!(
            "{:<6} {:<9} {:>12.4e} {:>12.6} {:>12.6} {:>9.2e}   (rapier, dt = 1/{:.0} s)",
            "ep",
            "rapier",
            xs[0],
            xs[1],
            xs[2],
            v_end,
            1.0 / dt
        );
    }
}
