//! Opens a scenario file in a window: the TOML scenarios that `stickslip run` steps headless
//! and streams to rerun (`scenarios/*.toml`) spawn as bevy entities, and their drivers (belts,
//! springs, force ramps) act on them. Without a file it opens the CLI's built-in scenario.
//!
//! Dynamic bodies are coloured by the regime of their contacts (green sticking, orange
//! stick-slip, red sliding, white without contact; violet in contact under rapier's own
//! friction, for a body whose contacts no stickslip material governs); fixed bodies are grey,
//! kinematic ones blue. The contact gizmos show each contact's friction force and normal. The HUD shows the
//! scenario's name and description, the time, and the contacts by regime.
//!
//! The camera frames the moving bodies whole (their bounding boxes in the camera's field of
//! view), and the contact gizmos are scaled to the scene: the heaviest body's weight draws as
//! a quarter of the framed region.
//!
//! Keys: Space pause, S slow motion (×0.1), R reload the file and restart, G contact gizmos.
//!
//! A bevy_rapier app: the scenario's bodies are bevy_rapier entities (`RigidBody`, child
//! `Collider`s, `Friction`, …) with stickslip's components, bevy_rapier steps them in the
//! fixed schedule at the scenario's dt, stickslip brackets every step.
//!
//! ```sh
//! cargo run --release -p stickslip-bevy-rapier --features window,scenario --example view -- \
//!     scenarios/belt_stick_slip.toml
//! # No display: under Xvfb, render 90 frames of 1/30 s simulated time, save the window, exit.
//! xvfb-run -a -s "-screen 0 1280x720x24" cargo run -p stickslip-bevy-rapier \
//!     --features window,scenario --example view -- scenarios/incline.toml \
//!     --screenshot incline.png --frames 90
//! ```

use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use bevy_rapier3d::rapier::geometry::ShapeType;
use std::path::PathBuf;
use stickslip_bevy_rapier::debug::{StickSlipDebugPlugin, StickSlipGizmos, regime_color};
use stickslip_bevy_rapier::scenario::{
    DriverAction, LoadedScenario, Scenario, StickSlipScenarioPlugin, despawn_scenario,
    spawn_scenario,
};
use stickslip_bevy_rapier::window::{
    Hud, WINDOW_SIZE, WindowedApp, command_line, hud_box, time_keys,
};
use stickslip_bevy_rapier::{StickSlipContacts, StickSlipRapier, StickSlipRapierPlugin};
use stickslip_core::law::Regime;

fn main() -> AppExit {
    // Without a file: the built-in scenario of `stickslip run`.
    let usage = "view [SCENARIO.toml] [--screenshot PATH] [--frames N]";
    let Some((shot, files)) = command_line(usage, 120, 1) else {
        return AppExit::error();
    };
    // Errors in the file (with field and line) before any window opens.
    let source = Source(files.into_iter().next().map(PathBuf::from));
    let scenario = match source.load() {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            return AppExit::error();
        }
    };
    let mut app = App::new();
    app.add_plugins(WindowedApp::new(format!("stickslip: {}", scenario.name)))
        // bevy_rapier in the fixed schedule (its timestep set to the scenario's dt on load),
        // stickslip beside it, the contact gizmos, the scenario's drivers.
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default().in_fixed_schedule())
        .add_plugins((
            StickSlipRapierPlugin::default().in_fixed_schedule(),
            StickSlipDebugPlugin,
            StickSlipScenarioPlugin::new(FixedUpdate),
        ))
        .insert_resource(source)
        .insert_resource(Current(scenario))
        .add_systems(Startup, (setup, load).chain())
        .add_systems(
            Update,
            (
                keys,
                time_keys,
                add_meshes,
                colour_bodies,
                draw_springs,
                hud,
            )
                .chain(),
        );
    if let Some(shot) = shot {
        // Reproducible pictures: the window at a given frame, every frame 1/30 s.
        app.add_plugins(shot);
    }
    app.run()
}

/// Where the scenario comes from: a file (read again on reload) or the built-in one.
#[derive(Resource, Clone)]
struct Source(Option<PathBuf>);

impl Source {
    fn load(&self) -> Result<Scenario, String> {
        match &self.0 {
            Some(path) => {
                let scenario = Scenario::from_path(path).map_err(|e| e.to_string())?;
                scenario
                    .build()
                    .map_err(|e| format!("{}: {e}", path.display()))?;
                Ok(scenario)
            }
            None => Ok(Scenario::builtin()),
        }
    }
}

/// The scenario on screen.
#[derive(Resource)]
struct Current(Scenario);

/// A dynamic body's collider, painted by the regime of its contacts.
#[derive(Component)]
struct Part;

/// Materials of the regimes (sticking, stick-slip, sliding), of no contact, and of contacts
/// under rapier's own friction.
#[derive(Resource)]
struct Palette([Handle<StandardMaterial>; 5]);

/// Colour of a body in contact under rapier's own friction (no stickslip report).
const RAPIER_FRICTION: Color = Color::srgb(0.62, 0.45, 0.85);

fn setup(mut commands: Commands, mut materials: ResMut<Assets<StandardMaterial>>) {
    let regimes = [Regime::Sticking, Regime::StickSlip, Regime::Sliding];
    let paint = |c: Color| StandardMaterial {
        base_color: c,
        perceptual_roughness: 0.7,
        ..default()
    };
    commands.insert_resource(Palette(std::array::from_fn(|i| {
        materials.add(paint(match i {
            0..=2 => regime_color(regimes[i]),
            3 => Color::WHITE,
            _ => RAPIER_FRICTION,
        }))
    })));
    commands.spawn((
        DirectionalLight {
            illuminance: 9_000.0,
            shadow_maps_enabled: true,
            ..default()
        },
        Transform::from_xyz(3.0, 8.0, 5.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    commands.insert_resource(GlobalAmbientLight {
        brightness: 400.0,
        ..default()
    });
    commands.spawn((Camera3d::default(), Transform::default()));
    commands.spawn(hud_box());
}

/// Spawns the current scenario, frames its moving bodies and scales the gizmos to it.
fn load(world: &mut World) {
    let scenario = world.resource::<Current>().0.clone();
    if let Err(e) = spawn_scenario(world, &scenario) {
        error!("{e}");
        world.write_message(AppExit::error());
        return;
    }
    let loaded = world.resource::<LoadedScenario>();
    let fov = PerspectiveProjection::default().fov;
    let camera = loaded.framing(fov, WINDOW_SIZE.0 as f32 / WINDOW_SIZE.1 as f32);
    let size = (loaded.region.1 - loaded.region.0).length();
    let weight = loaded.max_weight();
    let mut cameras = world.query_filtered::<&mut Transform, With<Camera3d>>();
    for mut t in cameras.iter_mut(world) {
        *t = camera;
    }
    // Arrows: the heaviest body's weight is a quarter of the region (friction is less).
    let mut store = world.resource_mut::<GizmoConfigStore>();
    let (config, gizmos) = store.config_mut::<StickSlipGizmos>();
    config.line.width = 2.5;
    gizmos.force_scale = if weight > 0.0 {
        0.25 * size / weight
    } else {
        0.0
    };
    gizmos.normal_length = 0.06 * size;
    gizmos.point_radius = 0.008 * size;
}

fn keys(
    mut commands: Commands,
    keys: Res<ButtonInput<KeyCode>>,
    mut gizmos: ResMut<GizmoConfigStore>,
    source: Res<Source>,
) {
    if keys.just_pressed(KeyCode::KeyG) {
        gizmos.config_mut::<StickSlipGizmos>().0.enabled ^= true;
    }
    if keys.just_pressed(KeyCode::KeyR) {
        // Read the file again (edit, press R); a broken edit keeps the running scenario.
        match source.load() {
            Ok(s) => {
                commands.insert_resource(Current(s));
                commands.queue(|world: &mut World| {
                    despawn_scenario(world);
                    load(world);
                });
            }
            Err(e) => error!("not reloaded: {e}"),
        }
    }
}

/// Meshes for new scenario colliders, from their rapier shapes.
fn add_meshes(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    palette: Res<Palette>,
    loaded: Option<Res<LoadedScenario>>,
    colliders: Query<(Entity, &Collider, &ChildOf), Added<Collider>>,
    bodies: Query<&RigidBody>,
) {
    let Some(loaded) = loaded else {
        return;
    };
    for (entity, collider, parent) in &colliders {
        if !loaded.colliders.contains(&entity) {
            continue;
        }
        let shape = &collider.raw;
        let mesh: Mesh = match shape.shape_type() {
            ShapeType::Cuboid => {
                let h = shape.as_cuboid().unwrap().half_extents;
                Cuboid::new(2.0 * h.x, 2.0 * h.y, 2.0 * h.z).into()
            }
            ShapeType::Ball => Sphere::new(shape.as_ball().unwrap().radius).into(),
            ShapeType::Capsule => {
                let c = shape.as_capsule().unwrap();
                Capsule3d::new(c.radius, c.segment.length()).into()
            }
            other => {
                warn!("no mesh for a {other:?} collider");
                continue;
            }
        };
        let kind = bodies.get(parent.parent()).ok();
        let material = match kind {
            Some(RigidBody::Dynamic) => palette.0[3].clone(),
            Some(RigidBody::Fixed) => materials.add(StandardMaterial {
                base_color: Color::srgb(0.45, 0.47, 0.5),
                perceptual_roughness: 0.8,
                ..default()
            }),
            _ => materials.add(StandardMaterial {
                base_color: Color::srgb(0.35, 0.55, 0.9),
                perceptual_roughness: 0.8,
                ..default()
            }),
        };
        commands
            .entity(entity)
            .insert((Mesh3d(meshes.add(mesh)), MeshMaterial3d(material)));
        if kind == Some(&RigidBody::Dynamic) {
            commands.entity(entity).insert(Part);
        }
        // Visible children need a visible parent (bevy's hierarchy rule B0004).
        commands
            .entity(parent.parent())
            .insert(Visibility::default());
    }
}

/// Dynamic bodies' colliders in the colour of their contacts' regime (white without contact,
/// violet in contact under rapier's own friction).
fn colour_bodies(
    contacts: Res<StickSlipContacts>,
    palette: Res<Palette>,
    rapier: ReadRapierContext,
    mut parts: Query<(Entity, &mut MeshMaterial3d<StandardMaterial>), With<Part>>,
) {
    let rapier = rapier.single().ok();
    for (e, mut material) in &mut parts {
        let i = match contacts.regime_of(e) {
            Some(Regime::Sticking) => 0,
            Some(Regime::StickSlip) => 1,
            Some(Regime::Sliding) => 2,
            // No stickslip report: touching anything is rapier's own friction.
            None if rapier
                .as_ref()
                .is_some_and(|r| r.contact_pairs_with(e).any(|p| p.has_any_active_contact())) =>
            {
                4
            }
            None => 3,
        };
        if material.0 != palette.0[i] {
            material.0 = palette.0[i].clone();
        }
    }
}

/// Spring drivers as yellow zigzags from their (moving) anchor to the body point.
fn draw_springs(
    loaded: Option<Res<LoadedScenario>>,
    stickslip: Res<StickSlipRapier>,
    bodies: Query<&GlobalTransform>,
    mut gizmos: Gizmos,
) {
    let Some(loaded) = loaded else {
        return;
    };
    let t = stickslip.modifier().time() - loaded.start_time;
    for d in loaded.drivers() {
        let DriverAction::Spring {
            anchor,
            anchor_velocity,
            point,
            ..
        } = &d.action
        else {
            continue;
        };
        let Ok(body) = bodies.get(loaded.bodies[d.body].entity) else {
            continue;
        };
        let a = Vec3::from_array(std::array::from_fn(|k| {
            (anchor[k] + anchor_velocity[k] * t) as f32
        }));
        let p = body.transform_point(*point);
        let along = p - a;
        let side = along.any_orthonormal_vector() * 0.02;
        let points = (0..=16).map(|i| {
            let wiggle = match i {
                0 | 16 => 0.0,
                _ if i % 2 == 0 => 1.0,
                _ => -1.0,
            };
            a + along * (i as f32 / 16.0) + side * wiggle
        });
        gizmos.linestrip(points, Color::srgb(1.0, 0.85, 0.2));
        gizmos.sphere(
            Isometry3d::from_translation(a),
            0.015,
            Color::srgb(1.0, 0.85, 0.2),
        );
    }
}

fn hud(
    stickslip: Res<StickSlipRapier>,
    time: Res<Time<Virtual>>,
    loaded: Option<Res<LoadedScenario>>,
    mut text: Query<&mut Text, With<Hud>>,
) {
    let (Ok(mut text), Some(loaded)) = (text.single_mut(), loaded) else {
        return;
    };
    let totals = stickslip.modifier().totals().unwrap_or_default();
    let state = match (time.is_paused(), time.relative_speed() < 1.0) {
        (true, _) => "   [paused]",
        (false, true) => "   [slow motion x0.1]",
        _ => "",
    };
    text.0 = format!(
        "stickslip scenario: {name}    t = {t:.2} s{state}\n\
         {description}\n\
         \n\
         {bodies} bodies;  contacts  {st} sticking, {ss} stick-slip, {sl} sliding;  \
         friction dissipates {pw:.3} W\n\
         bodies    green sticking, orange stick-slip, red sliding, white no contact, \
         violet rapier's own friction\n\
         keys      Space pause  S slow motion  R reload + restart  G gizmos",
        name = loaded.name,
        t = stickslip.modifier().time() - loaded.start_time,
        description = wrap(&loaded.description, 100),
        bodies = loaded.bodies.len(),
        st = totals.sticking,
        ss = totals.stick_slip,
        sl = totals.sliding,
        pw = totals.dissipated_power,
    );
}

/// Breaks `text` into lines of at most about `width` characters.
fn wrap(text: &str, width: usize) -> String {
    let mut out = String::new();
    let mut line = 0;
    for word in text.split_whitespace() {
        if line > 0 && line + 1 + word.len() > width {
            out.push('\n');
            line = 0;
        } else if line > 0 {
            out.push(' ');
            line += 1;
        }
        out.push_str(word);
        line += word.len();
    }
    out
}
