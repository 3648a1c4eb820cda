//! Contact read-back. Invariants: `ContactReports` holds one entry per stickslip contact,
//! mapped to the colliders' entities, with its point in world space between the part and
//! the surface it rests on (also on a tilted, shifted trough and for a part in any rotation),
//! the surface normal, the weight as normal force, the regime per entity (`regime_of`) and
//! totals that add up.

mod common;
use bevy::prelude::*;
use common::*;
use stickslip_bevy::prelude::*;

#[test]
fn reports_map_to_entities_with_world_points() {
    let mut app = app();
    // A trough tilted by 10° about z and shifted, with parts resting on it (sticking: μ 0.5
    // holds up to 26.6°).
    let tilt = Quat::from_rotation_z(-10f32.to_radians());
    let centre = Vec3::new(3.0, -1.0, 2.0);
    let trough = app
        .world_mut()
        .spawn((
            RigidBody::Fixed,
            Collider::cuboid(2.0, 0.1, 0.5),
            FrictionLaw::new(ep(1e5, 0.5, 0.5)),
            Transform::from_translation(centre).with_rotation(tilt),
        ))
        .id();
    let parts: Vec<(Entity, Vec3)> = [-1.0f32, 0.0, 1.0]
        .iter()
        .map(|&along| {
            let at = centre + tilt * Vec3::new(along, 0.2, 0.0);
            let e = app
                .world_mut()
                .spawn((
                    RigidBody::Dynamic,
                    Collider::cuboid(0.1, 0.1, 0.1),
                    Transform::from_translation(at).with_rotation(tilt),
                ))
                .id();
            (e, at)
        })
        .collect();
    steps(&mut app, 60);
    let reports = app.world().resource::<ContactReports>();
    assert_eq!(reports.contacts.len(), 3);
    assert_eq!(reports.totals.contacts, 3);
    assert_eq!(reports.totals.sticking, 3);
    let up = tilt * Vec3::Y;
    for (e, at) in &parts {
        let c: Vec<&Contact> = reports.of(*e).collect();
        assert_eq!(c.len(), 1);
        let c = c[0];
        assert!(c.involves(trough));
        // Half a part below its centre, on the trough's surface.
        let expect = *at - 0.1 * up;
        assert!(
            (c.point - expect).length() < 2e-3,
            "point {} vs {expect}",
            c.point
        );
        assert!(c.normal.dot(up).abs() > 0.999, "normal {}", c.normal);
        let weight = 8.0 * 9.81 * up.dot(Vec3::Y) as f64;
        assert!((c.report.normal_force - weight).abs() < 0.02 * weight);
        assert_eq!(reports.regime_of(*e), Some(Regime::Sticking));
    }
    assert_eq!(reports.regime_of(trough), Some(Regime::Sticking));
    let total: f64 = reports.contacts.iter().map(|c| c.report.normal_force).sum();
    assert!((total - reports.totals.normal_force).abs() < 1e-9);
}
