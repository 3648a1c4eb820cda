//! Debug gizmos: every stickslip contact as a dot coloured by regime (green sticking, orange
//! stick-slip, red sliding), its friction force as an arrow in the same colour and its normal
//! as a white ray.

use crate::contacts::ContactReports;
use bevy::gizmos::GizmoPlugin;
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use stickslip_core::law::Regime;

/// Settings of the contact gizmos. Toggle them with
/// `GizmoConfigStore::config_mut::<StickSlipGizmos>().0.enabled`.
#[derive(Reflect, GizmoConfigGroup, Debug, Clone)]
pub struct StickSlipGizmos {
    /// Metres of arrow per newton of friction force.
    pub force_scale: f32,
    /// Length of the normal ray (m); 0 hides normals.
    pub normal_length: f32,
    /// Radius of the contact dot (m).
    pub point_radius: f32,
}

impl Default for StickSlipGizmos {
    fn default() -> Self {
        StickSlipGizmos {
            force_scale: 0.02,
            normal_length: 0.05,
            point_radius: 0.01,
        }
    }
}

/// The colour of a regime: green sticking, orange stick-slip, red sliding.
pub fn regime_color(regime: Regime) -> Color {
    match regime {
        Regime::Sticking => Color::srgb(0.2, 0.85, 0.3),
        Regime::StickSlip => Color::srgb(1.0, 0.6, 0.1),
        Regime::Sliding => Color::srgb(0.95, 0.2, 0.2),
    }
}

/// Draws the contacts of [`ContactReports`] in `PostUpdate`, after transform propagation.
/// It needs bevy's `GizmoPlugin` (in `DefaultPlugins` with bevy's gizmo features) and does
/// nothing without it, so the plugin group stays usable headless; it looks in
/// [`Plugin::finish`], when every plugin is in, so the order of `add_plugins` does not matter.
pub struct StickSlipDebugPlugin;

impl Plugin for StickSlipDebugPlugin {
    fn build(&self, _app: &mut App) {}

    fn finish(&self, app: &mut App) {
        if !app.is_plugin_added::<GizmoPlugin>() {
            debug!("stickslip contact gizmos off: no GizmoPlugin in this app");
            return;
        }
        // Drawn on top: contacts hide under the parts.
        let config = GizmoConfig {
            depth_bias: -1.0,
            ..default()
        };
        app.insert_gizmo_config(StickSlipGizmos::default(), config)
            .add_systems(
                PostUpdate,
                draw_contacts.after(TransformSystems::Propagate).run_if(
                    |store: Res<GizmoConfigStore>| store.config::<StickSlipGizmos>().0.enabled,
                ),
            );
    }
}

fn draw_contacts(contacts: Res<ContactReports>, mut gizmos: Gizmos<StickSlipGizmos>) {
    let cfg = gizmos.config_ext.clone();
    for c in &contacts.contacts {
        let (r, p) = (&c.report, c.point);
        let color = regime_color(r.regime);
        gizmos.sphere(p, cfg.point_radius, color);
        let f = Vec3::from_array(r.friction_force) * cfg.force_scale;
        if f.length() > 1e-4 {
            gizmos.arrow(p, p + f, color);
        }
        if cfg.normal_length > 0.0 {
            gizmos.ray(p, c.normal * cfg.normal_length, Color::WHITE);
        }
    }
}
