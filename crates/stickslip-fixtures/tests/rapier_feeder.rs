//! A vibratory feeder in a real rapier world: a kinematic trough vibrating along a throw angle
//! (0.5–2 mm, 20–40 Hz, 15–33°, throw numbers 0.8–1.7, so that the part hops) carries one
//! part forward. Invariants: plain rapier at a fine step (1/30 000 s) is within 3 % of the
//! independent rigid-body reference of stickslip-theory (`stickslip_theory::feeder`: point mass, exact
//! ballistic flight, plastic landing with Coulomb impact friction); with the elasto-plastic law
//! (c = 1e5 1/m, g_ba = 5 µm) the transport speed is within 3 % of plain rapier (Coulomb, same
//! μ) at the same step (1/3000 s): nothing of the contact state survives the flight or brakes
//! the landing. At the fine step the EP contact's tangential compliance k_t = c F̄ shows under a
//! normal load that drops to zero every period (Popov's mechanism lowers the mean friction), so
//! EP approaches the rigid reference as c grows: its deviation does not grow from c = 1e5 to
//! 1e7, and at c = 1e7 (g_ba = 50 nm) it is within 3 %.
// 3D only: in 2D (stickslip-fixtures2d) EP at c = 1e5 and dt 1/3000 carries the part 13 %
// slower than plain rapier2d in the first case (0.0612 against 0.0705 m/s), as both dimensions
// do at the fine step (0.0596 against 0.0686), where 3D's coarse step agrees within 1 %: to be
// understood before the 3 % claim is made for 2D.
#![cfg(not(dim2))]

use stickslip_fixtures::feeder_speed;
use stickslip_theory::feeder::VibratoryFeeder;

const MU: f64 = 0.5;
const G: f64 = 9.81;

/// Mean transport speed of the part in rapier over 20 periods after 20, with stickslip's EP
/// law (`Some(c)`) or plain friction.
fn rapier_speed(feeder: &VibratoryFeeder, f: f64, dt: f64, ep: Option<f64>) -> f64 {
    feeder_speed(feeder, f, MU, dt, ep, 20, 20).unwrap()
}

#[test]
fn feeder_transport_speed_matches_plain_rapier_and_the_rigid_body_reference() {
    let cases = [
        (1e-3, 25.0, 25.0),
        (0.5e-3, 40.0, 30.0),
        (2e-3, 20.0, 15.0),
        (1e-3, 28.0, 33.0),
    ];
    for (a, f, beta_deg) in cases {
        let feeder = VibratoryFeeder::new(a, f, f64::to_radians(beta_deg), MU, G).unwrap();
        let reference = feeder.transport_speed(20, 20);
        let coarse = 1.0 / 3000.0;
        let ep = rapier_speed(&feeder, f, coarse, Some(1e5));
        let plain = rapier_speed(&feeder, f, coarse, None);
        let fine = 1.0 / 30000.0;
        let plain_fine = rapier_speed(&feeder, f, fine, None);
        let ep_fine: Vec<f64> = [1e5, 1e6, 1e7]
            .iter()
            .map(|&c| rapier_speed(&feeder, f, fine, Some(c)))
            .collect();
        println!(
            "A {a} m, f {f} Hz, throw {beta_deg}°, Γ {:.2}: reference {reference:.5} m/s; \
             dt 1/3000: EP {ep:.5}, plain {plain:.5}; dt 1/30000: plain {plain_fine:.5}, \
             EP c = 1e5/1e6/1e7: {:.5} {:.5} {:.5}",
            feeder.throw_number(),
            ep_fine[0],
            ep_fine[1],
            ep_fine[2]
        );
        let rel = |x: f64, y: f64| (x - y).abs() / y;
        assert!(
            rel(plain_fine, reference) < 0.03,
            "plain {plain_fine} vs reference {reference}"
        );
        assert!(
            rel(ep, plain) < 0.03,
            "EP {ep} vs plain {plain} at dt 1/3000"
        );
        let dev: Vec<f64> = ep_fine.iter().map(|&v| rel(v, reference)).collect();
        assert!(
            dev[1] <= dev[0] + 0.005 && dev[2] <= dev[1] + 0.005,
            "EP deviations {dev:?}"
        );
        assert!(
            dev[2] < 0.03,
            "EP at c = 1e7: {} vs reference {reference}",
            ep_fine[2]
        );
    }
}
