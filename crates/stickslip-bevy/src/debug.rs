//! Contact gizmos (feature `debug`): every contact of [`crate::StickSlipContacts`] as a dot
//! coloured by regime (green sticking, orange stick-slip, red sliding), its friction force as
//! an arrow in that colour and its normal as a white ray. Needs bevy's `GizmoPlugin`; the
//! add-ons read contacts back while this plugin is in the app.

use crate::StickSlipContacts;
use bevy::gizmos::GizmoPlugin;
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use stickslip_core::law::Regime;

/// Settings of the contact gizmos; toggle them with
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

/// The colour of a regime (`Regime::srgb`, shared with rerun): green sticking, orange
/// stick-slip, red sliding.
pub fn regime_color(regime: Regime) -> Color {
    let [r, g, b] = regime.srgb();
    Color::srgb_u8(r, g, b)
}

/// Draws the contacts in `PostUpdate` after transform propagation; does nothing without
/// bevy's `GizmoPlugin` (looked for in [`Plugin::finish`], so plugin order does not matter).
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

fn draw_contacts(contacts: Option<Res<StickSlipContacts>>, mut gizmos: Gizmos<StickSlipGizmos>) {
    let Some(contacts) = contacts else { return };
    let cfg = gizmos.config_ext.clone();
    for c in contacts.0.iter().filter(|c| !c.reset) {
        let p = Vec3::from(c.point);
        let color = regime_color(c.regime);
        gizmos.sphere(p, cfg.point_radius, color);
        let f = Vec3::from(c.friction_force) * cfg.force_scale;
        if f.length() > 1e-4 {
            gizmos.arrow(p, p + f, color);
        }
        if cfg.normal_length > 0.0 {
            gizmos.ray(p, Vec3::from(c.normal) * cfg.normal_length, Color::WHITE);
        }
    }
}
