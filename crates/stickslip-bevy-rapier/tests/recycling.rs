//! Quiet contacts recycle in a bevy_rapier app as with plain rapier: three stacks of three
//! boxes resting on an attached ground (every collider with `StickSlipFriction`, sleeping off
//! so that every pair stays awake) have their stickslip hook flags turned off once settled, so
//! rapier recycles their pairs, and the top boxes stay where plain bevy_rapier leaves them
//! (within g_ba = μ_ba/c). A collider whose `ActiveHooks` component the app gives the flag
//! keeps it on and its pairs hooked (the app's hooks need it every step); taking the flag out
//! of the component hands it back to stickslip, which recycles the collider again.

mod common;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_rapier3d::plugin::context::RapierContextColliders;
use bevy_rapier3d::prelude::*;
use bevy_rapier3d::rapier::pipeline::ActiveHooks as RapierHooks;
use std::time::Duration;
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier};

const DT: f32 = 1.0 / 60.0;
const C: f64 = 1e4;
const MU: f64 = 0.5;

/// Three stacks of three 0.2 m boxes on a 0.2 m thick ground; with `stickslip`, every
/// collider attached. Returns (ground, top boxes, every box).
fn stacks(app: &mut App, stickslip: bool) -> (Entity, Vec<Entity>, Vec<Entity>) {
    let law = common::ep(C, MU, MU);
    let world = app.world_mut();
    let ground = world
        .spawn((
            RigidBody::Fixed,
            Collider::cuboid(5.0, 0.1, 5.0),
            Transform::default(),
        ))
        .id();
    let (mut tops, mut boxes) = (Vec::new(), Vec::new());
    for x in [-1.0, 0.0, 1.0] {
        for level in 0..3 {
            let b = world
                .spawn((
                    RigidBody::Dynamic,
                    Collider::cuboid(0.1, 0.1, 0.1),
                    Transform::from_xyz(x, 0.2 + 0.2 * level as f32, 0.0),
                    Sleeping::disabled(),
                ))
                .id();
            boxes.push(b);
            if level == 2 {
                tops.push(b);
            }
        }
    }
    if stickslip {
        for &e in boxes.iter().chain([&ground]) {
            world
                .entity_mut(e)
                .insert(StickSlipFriction(Some(law.clone())));
        }
    }
    (ground, tops, boxes)
}

fn plain_app() -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed {
            dt: DT,
            substeps: 1,
        })
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
            DT,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default());
    app.update();
    app
}

fn handle(app: &App, e: Entity) -> bevy_rapier3d::rapier::geometry::ColliderHandle {
    app.world().get::<RapierColliderHandle>(e).unwrap().0
}

fn recycled(app: &App, e: Entity) -> bool {
    let h = handle(app, e);
    app.world()
        .resource::<StickSlipRapier>()
        .modifier()
        .is_recycled(h)
}

fn rapier_flag(app: &mut App, e: Entity) -> bool {
    let h = handle(app, e);
    let mut q = app.world_mut().query::<&RapierContextColliders>();
    q.single(app.world()).unwrap().colliders[h]
        .active_hooks()
        .contains(RapierHooks::MODIFY_SOLVER_CONTACTS)
}

fn position(app: &App, e: Entity) -> Vec3 {
    app.world().get::<Transform>(e).unwrap().translation
}

#[test]
fn resting_stacks_recycle_and_stay_put() {
    let mut plain = plain_app();
    let (_, plain_tops, _) = stacks(&mut plain, false);
    let mut app = common::app(
        TimestepMode::Fixed {
            dt: DT,
            substeps: 1,
        },
        DT as f64,
    );
    let (ground, tops, boxes) = stacks(&mut app, true);
    // Settled, then measured over 5 s.
    common::steps(&mut plain, 60);
    common::steps(&mut app, 60);
    let start_plain: Vec<Vec3> = plain_tops.iter().map(|&e| position(&plain, e)).collect();
    let start: Vec<Vec3> = tops.iter().map(|&e| position(&app, e)).collect();
    common::steps(&mut plain, 300);
    common::steps(&mut app, 300);
    for &e in boxes.iter().chain([&ground]) {
        assert!(recycled(&app, e), "{e:?} not recycled");
        assert!(
            !rapier_flag(&mut app, e),
            "{e:?} still carries stickslip's flag"
        );
    }
    let g_ba = MU / C;
    for (k, (&e, &p)) in plain_tops.iter().zip(&start_plain).enumerate() {
        let moved_plain = (position(&plain, e) - p).length() as f64;
        let moved = (position(&app, tops[k]) - start[k]).length() as f64;
        assert!(
            moved <= moved_plain + g_ba,
            "top box {k} moved {moved:e} m, plain bevy_rapier {moved_plain:e} m"
        );
    }

    // The app flags the ground: its hooks need it every step, so it stays on.
    app.world_mut()
        .entity_mut(ground)
        .insert(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    common::steps(&mut app, 60);
    assert!(rapier_flag(&mut app, ground));
    assert!(!recycled(&app, ground));
    // And takes it out again: the flag is stickslip's, which recycles the ground again.
    app.world_mut()
        .entity_mut(ground)
        .insert(ActiveHooks::empty());
    common::steps(&mut app, 60);
    assert!(recycled(&app, ground));
    assert!(!rapier_flag(&mut app, ground));
    for (k, &e) in tops.iter().enumerate() {
        let moved = (position(&app, e) - start[k]).length() as f64;
        assert!(
            moved < 1e-3,
            "top box {k} moved {moved:e} m over the flag changes"
        );
    }
}
