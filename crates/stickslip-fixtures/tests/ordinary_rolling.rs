//! Things that roll, with stickslip attached to every collider (default configuration), beside
//! plain rapier in the same test. Invariants: a ball, a solid cylinder and a capsule on a slope
//! below the no-slip limit (tan θ < μ (1 + m r²/I)) roll without slipping at
//! a = g sin θ / (1 + I/(m r²)) within 2 %, their contact point slipping no more than
//! under plain rapier (+5 mm/s) and, for the laws that stick (not Regul, which creeps by
//! design), the slip accumulated at the contact, Σ (v + ω r) dt over 1.5 s, within 5 % of
//! plain rapier's own + 0.1 mm (also with static above kinetic friction; at 60 Hz plain
//! rapier's rolling contacts themselves slip 1–2 cm, mostly at the start); above the limit they
//! roll with slip at a = g (sin θ − μ cos θ) and spin up at ω̇ = μ m g r cos θ / I within 2 % (or plain rapier's own error + 0.5 %);
//! at 60 Hz and 240 Hz, for every law (EP, Phys, Coulomb, Regul). A cart on four cylinder
//! wheels on revolute joints, pushed, accelerates at F / (M + Σ (m_w + I_w/r²)) within 2 % and
//! coasts, its wheels not slipping. A box pulled across the ground with balls rolling on its
//! top follows a_box = (F − μ (M + Σm) g)/(M + Σ (2/7) m), the balls (2/7) a_box, within 2 %,
//! the balls slipping on the box no more than under plain rapier (a few mm/s). In 2D
//! (stickslip-fixtures2d) the rollers are a disc (a ball collider); the cart and the balls on
//! a box are 3D.

mod ordinary;

use ordinary::{Friction, Run, all_laws, ep, rel};
use stickslip_fixtures::dim::spin_z;
#[cfg(not(dim2))]
use stickslip_fixtures::ordinary::{CART_WHEEL_RADIUS, box_with_balls, cart};
use stickslip_fixtures::ordinary::{Ground, Roller, roll_inertia_ratio, roller_on_slope};
#[cfg(not(dim2))]
use stickslip_rapier::rapier::prelude::*;

/// The rollers of the dimension: in 2D a disc.
#[cfg(not(dim2))]
const ROLLERS: [Roller; 3] = [Roller::Ball, Roller::Cylinder, Roller::Capsule];
#[cfg(dim2)]
const ROLLERS: [Roller; 1] = [Roller::Ball];

const G: f64 = 9.81;
const R: f32 = 0.2;

struct Rolled {
    /// Acceleration along the slope (m/s²).
    accel: f64,
    /// Spin-up rate about the roll axis (rad/s², positive rolling down the slope).
    spin_up: f64,
    /// Largest contact-point slip speed |v + ω × r| seen (m/s).
    max_slip: f64,
    /// Slip accumulated at the contact point, Σ (v + ω × r) dt (m).
    creep: f64,
    /// I / (m r²) of the body.
    k: f64,
}

fn roll(roller: Roller, tan_theta: f64, mu: f64, dt: f64, friction: &Friction) -> Rolled {
    let scene = roller_on_slope(roller, R, Ground::Cuboid, tan_theta, mu as f32, dt);
    let k = roll_inertia_ratio(&scene.world, scene.bodies[0], R);
    let mut run = Run::new(scene, friction);
    // Let the contact form (the body starts touching), then measure over 1.5 s.
    run.run_for(0.25);
    let (v0, w0) = (run.body(0).linvel().x as f64, -spin_z(run.body(0)) as f64);
    let n = (1.5 / dt).round() as usize;
    let (mut max_slip, mut creep): (f64, f64) = (0.0, 0.0);
    for _ in 0..n {
        run.step();
        let b = run.body(0);
        // The bottom point: v + ω ẑ × (−r ŷ) = v + ω r x̂ (positions advance by the new
        // velocities, so the sum is Δx + r Δφ).
        let slip = (b.linvel().x + spin_z(b) * R) as f64;
        max_slip = max_slip.max(slip.abs());
        creep += slip * dt;
    }
    let t = n as f64 * dt;
    let b = run.body(0);
    Rolled {
        accel: (b.linvel().x as f64 - v0) / t,
        spin_up: (-spin_z(b) as f64 - w0) / t,
        max_slip,
        creep,
        k,
    }
}

fn slope_sin_cos(tan_theta: f64) -> (f64, f64) {
    let th = tan_theta.atan();
    (th.sin(), th.cos())
}

#[test]
fn rollers_roll_without_slipping_below_the_limit() {
    let (tan_theta, mu) = (0.3, 0.5);
    let (s, _) = slope_sin_cos(tan_theta);
    let mut failures = Vec::new();
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for roller in ROLLERS {
            let plain = roll(roller, tan_theta, mu, dt, &Friction::Plain);
            let expected = G * s / (1.0 + plain.k);
            println!(
                "{roller:?} at {:.0} Hz: closed form {expected:.4} m/s² (I/mr² {:.4}); plain {:+.2} % (slip ≤ {:.1e} m/s, creep {:.3e} m)",
                1.0 / dt,
                plain.k,
                100.0 * rel(plain.accel, expected),
                plain.max_slip,
                plain.creep
            );
            let mut laws = all_laws(mu);
            laws.push(Friction::Law("ep 0.5/0.4", ep(mu, 0.4)));
            for f in laws {
                let r = roll(roller, tan_theta, mu, dt, &f);
                let e = rel(r.accel, expected);
                println!(
                    "    {:10} {:+.2} %  slip ≤ {:.1e} m/s, creep {:.3e} m",
                    f.name(),
                    100.0 * e,
                    r.max_slip,
                    r.creep
                );
                // The contact point's slip within 5 mm/s of plain rapier's own (at 60 Hz the
                // solver leaves both ~2 cm/s at the start), and no more creep than plain
                // rapier's (5 % + 0.1 mm) for the laws that stick.
                let crept = f.name() != "regul" && r.creep.abs() > 1.05 * plain.creep.abs() + 1e-4;
                if e.abs() > 0.02 || r.max_slip > plain.max_slip + 0.005 || crept {
                    failures.push(format!("{roller:?} {} at {:.0} Hz", f.name(), 1.0 / dt));
                }
            }
        }
    }
    assert!(failures.is_empty(), "did not roll: {failures:?}");
}

#[test]
fn rollers_roll_with_slip_above_the_limit() {
    let (tan_theta, mu) = (0.5, 0.1);
    let (s, c) = slope_sin_cos(tan_theta);
    let expected = G * (s - mu * c);
    let mut failures = Vec::new();
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for roller in ROLLERS {
            let plain = roll(roller, tan_theta, mu, dt, &Friction::Plain);
            let spin = mu * G * c / (plain.k * R as f64);
            println!(
                "{roller:?} at {:.0} Hz: a {expected:.4} m/s², ω̇ {spin:.3} rad/s²; plain {:+.2} % / {:+.2} %",
                1.0 / dt,
                100.0 * rel(plain.accel, expected),
                100.0 * rel(plain.spin_up, spin)
            );
            for f in all_laws(mu) {
                let r = roll(roller, tan_theta, mu, dt, &f);
                let (ea, es) = (rel(r.accel, expected), rel(r.spin_up, spin));
                println!(
                    "    {:8} {:+.2} % / {:+.2} %",
                    f.name(),
                    100.0 * ea,
                    100.0 * es
                );
                // Within 2 % of the closed form, or of plain rapier's own error + 0.5 % where
                // plain rapier itself is further off (the cylinder's spin-up at 60 Hz: −2.0 %).
                let tol = |plain_err: f64| 0.02f64.max(plain_err.abs() + 0.005);
                if ea.abs() > tol(rel(plain.accel, expected))
                    || es.abs() > tol(rel(plain.spin_up, spin))
                {
                    failures.push(format!("{roller:?} {} at {:.0} Hz", f.name(), 1.0 / dt));
                }
            }
        }
    }
    assert!(failures.is_empty(), "wrong rolling with slip: {failures:?}");
}

#[cfg(not(dim2))]
#[test]
fn a_cart_on_wheels_accelerates_and_coasts_without_wheel_slip() {
    let (chassis, wheel, mu, force) = (20.0f32, 2.0f32, 0.6, 30.0f32);
    let dt = 1.0 / 60.0;
    let r = CART_WHEEL_RADIUS as f64;
    let run_cart = |f: &Friction| {
        let mut run = Run::new(cart(chassis, wheel, mu as f32, dt), f);
        run.run_for(0.5);
        let v0 = run.body(0).linvel().x as f64;
        run.body_mut(0)
            .add_force(Vector::new(force, 0.0, 0.0), true);
        let n = (1.0 / dt).round() as usize;
        let mut slip: f64 = 0.0;
        let wheel_slip = |run: &Run| {
            (1..5)
                .map(|i| {
                    let b = run.body(i);
                    (b.linvel().x + b.angvel().z * CART_WHEEL_RADIUS).abs() as f64
                })
                .fold(0.0, f64::max)
        };
        for _ in 0..n {
            run.step();
            slip = slip.max(wheel_slip(&run));
        }
        let a = (run.body(0).linvel().x as f64 - v0) / (n as f64 * dt);
        run.body_mut(0).reset_forces(true);
        let v1 = run.body(0).linvel().x as f64;
        for _ in 0..n {
            run.step();
            slip = slip.max(wheel_slip(&run));
        }
        let coast = (run.body(0).linvel().x as f64 - v1) / v1;
        (a, coast, slip)
    };
    // Wheel inertia about its axle: a solid cylinder, I = m r²/2.
    let m_eff = chassis as f64 + 4.0 * (wheel as f64 + 0.5 * wheel as f64);
    let expected = force as f64 / m_eff;
    let plain = run_cart(&Friction::Plain);
    println!(
        "cart: closed form {expected:.4} m/s²; plain {:+.2} %, coast {:+.2} %, wheel slip ≤ {:.1e} m/s",
        100.0 * rel(plain.0, expected),
        100.0 * plain.1,
        plain.2
    );
    let _ = r;
    for f in all_laws(mu) {
        let (a, coast, slip) = run_cart(&f);
        println!(
            "    {:8} {:+.2} %, coast {:+.2} %, wheel slip ≤ {slip:.1e} m/s",
            f.name(),
            100.0 * rel(a, expected),
            100.0 * coast
        );
        assert!(rel(a, expected).abs() < 0.02, "{}: a = {a}", f.name());
        assert!(coast.abs() < 0.02, "{}: coasting lost {coast}", f.name());
        assert!(slip < 0.01, "{}: wheels slip at {slip} m/s", f.name());
    }
}

#[cfg(not(dim2))]
#[test]
fn balls_roll_on_a_pulled_box() {
    let (balls, box_mass, ball_mass, mu, force) = (6usize, 10.0f32, 1.0f32, 0.3, 60.0f32);
    let dt = 1.0 / 60.0;
    let run_box = |f: &Friction| {
        let mut run = Run::new(box_with_balls(balls, box_mass, ball_mass, mu as f32, dt), f);
        run.run_for(0.5);
        let v0: Vec<f64> = (0..=balls).map(|i| run.body(i).linvel().x as f64).collect();
        run.body_mut(0)
            .add_force(Vector::new(force, 0.0, 0.0), true);
        let n = (1.0 / dt).round() as usize;
        let mut slip: f64 = 0.0;
        for _ in 0..n {
            run.step();
            let vb = run.body(0).linvel().x;
            for i in 1..=balls {
                let b = run.body(i);
                // Bottom point of the ball: v + ω × (−r ŷ), x component v_x + ω_z r.
                slip = slip.max((b.linvel().x + b.angvel().z * 0.1 - vb).abs() as f64);
            }
        }
        let t = n as f64 * dt;
        let a: Vec<f64> = (0..=balls)
            .map(|i| (run.body(i).linvel().x as f64 - v0[i]) / t)
            .collect();
        (a[0], a[1..].iter().sum::<f64>() / balls as f64, slip)
    };
    let (m, b, n) = (box_mass as f64, ball_mass as f64, balls as f64);
    let a_box = (force as f64 - mu * (m + n * b) * G) / (m + n * 2.0 / 7.0 * b);
    let a_ball = 2.0 / 7.0 * a_box;
    let plain = run_box(&Friction::Plain);
    println!(
        "box {a_box:.4}, balls {a_ball:.4} m/s²; plain {:+.2} % / {:+.2} %, slip ≤ {:.1e} m/s",
        100.0 * rel(plain.0, a_box),
        100.0 * rel(plain.1, a_ball),
        plain.2
    );
    for f in all_laws(mu) {
        let (ab, al, slip) = run_box(&f);
        println!(
            "    {:8} {:+.2} % / {:+.2} %, slip ≤ {slip:.1e} m/s",
            f.name(),
            100.0 * rel(ab, a_box),
            100.0 * rel(al, a_ball)
        );
        assert!(rel(ab, a_box).abs() < 0.02, "{}: box a = {ab}", f.name());
        assert!(rel(al, a_ball).abs() < 0.02, "{}: balls a = {al}", f.name());
        assert!(
            slip <= plain.2.max(0.005),
            "{}: balls slip at {slip} m/s (plain {})",
            f.name(),
            plain.2
        );
    }
}
