//! stickslip's [`PhysicsHooks`] impl: plumbing around [`crate::contact_step::step_contact`].
//! Per manifold it finds the contact's record, lets the wrapped hook run with its own
//! `user_data`, gathers the step's inputs from the manifold and the bodies (normal force and
//! measured friction of the last solve, the slip of the touching points at the centroid of the
//! solver contacts), and writes the friction limit and target velocity the step returns.
//! rapier keeps one friction coefficient and (by default in 3D, `FrictionModel::Simplified`)
//! one friction constraint per manifold, so stickslip keeps one friction state per manifold.

use crate::contact_step::{ContactInput, step_contact};
use crate::contact_store::{ContactKey, ContactRecord};
use crate::measure::{centroid, measure, point_velocity};
use crate::modifier::StickSlip;
use crate::tangent::TangentBasis;
use rapier3d::prelude::*;
use std::sync::atomic::Ordering;

fn key(c1: ColliderHandle, c2: ColliderHandle, m: &ContactManifold) -> ContactKey {
    let features = m.points.first().map_or(0, |p| {
        ((p.fid1.0 as u64) << 32 | p.fid2.0 as u64)
            ^ ((m.subshape1 as u64) << 17)
            ^ ((m.subshape2 as u64) << 47)
    });
    ContactKey { c1, c2, features }
}

fn inv_mass(bodies: &RigidBodySet, h: Option<RigidBodyHandle>) -> f64 {
    h.and_then(|h| bodies.get(h))
        .filter(|b| b.is_dynamic())
        .map_or(0.0, |b| {
            let m = b.mass() as f64;
            if m > 0.0 { 1.0 / m } else { 0.0 }
        })
}

impl<H: PhysicsHooks> PhysicsHooks for StickSlip<H> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        self.inner.filter_contact_pair(context)
    }

    fn filter_intersection_pair(&self, context: &PairFilterContext) -> bool {
        self.inner.filter_intersection_pair(context)
    }

    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let Some(rigid) = ctx.rigid() else {
            self.inner.modify_solver_contacts(ctx);
            return;
        };
        // A manifold without solver contacts and without a record (a pair inside the
        // prediction distance, not touching) has nothing for the law: no record is made
        // unless the wrapped hook keeps a value in its user_data.
        if rigid.solver_contacts.is_empty() && *rigid.user_data == 0 {
            self.inner.modify_solver_contacts(ctx);
            let Some(r) = ctx.rigid_mut() else { return };
            let inner_data = *r.user_data;
            if inner_data == 0 {
                return;
            }
            let key = key(c1, c2, r.manifold);
            let mut user_data = 0;
            self.store
                .with_record(&mut user_data, &key, self.clock.mark(), |rec, _, ours| {
                    rec.inner_user_data = inner_data;
                    *r.user_data = ours;
                });
            return;
        }
        let key = key(c1, c2, rigid.manifold);
        let mut user_data = *rigid.user_data;
        let step = self.clock.mark();
        // The manifold's user_data is ours; the inner hook sees its own value.
        self.store
            .with_record(&mut user_data, &key, step, |rec, _, ours| {
                if let Some(r) = ctx.rigid_mut() {
                    *r.user_data = rec.inner_user_data;
                }
                self.inner.modify_solver_contacts(ctx);
                if let Some(r) = ctx.rigid_mut() {
                    rec.inner_user_data = *r.user_data;
                    *r.user_data = ours;
                }
                self.apply(ctx, rec);
            });
    }
}

impl<H: PhysicsHooks> StickSlip<H> {
    fn apply(&self, ctx: &mut ContactModificationContext, rec: &mut ContactRecord) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let bodies = ctx.bodies;
        let (rb1, rb2) = (ctx.rigid_body1, ctx.rigid_body2);
        let material = self
            .materials
            .get(c1)
            .or_else(|| self.materials.get(c2))
            .unwrap_or(&self.default_material);
        let source = self.vibrations.get(c1).or_else(|| self.vibrations.get(c2));
        let rel = if self.vibrations.get(c1).is_some() {
            -1.0
        } else {
            1.0
        };
        let Some(m) = ctx.rigid_mut() else { return };
        let dt = self.clock.dt;
        if m.solver_contacts.is_empty() || !(dt > 0.0) {
            return;
        }
        let basis = TangentBasis::new(*m.normal);
        let (p, surface) = centroid(m.solver_contacts);
        if surface != Vector::ZERO && !self.moving_surfaces.load(Ordering::Relaxed) {
            self.moving_surfaces.store(true, Ordering::Relaxed);
        }
        // ġ = v₂ − v₁ of the touching material points (relative to a moving surface).
        let slip = basis
            .project(point_velocity(bodies, rb2, p) - point_velocity(bodies, rb1, p) - surface);
        let meas = measure(m.manifold, dt);
        let out = step_contact(
            rec,
            &ContactInput {
                law: &material.law,
                source,
                rel,
                basis: &basis,
                normal_force: meas.normal_force,
                measured_mu: basis.project(meas.mu),
                slip,
                dt,
                time: self.clock.time,
                inv_mass: inv_mass(bodies, rb1) + inv_mass(bodies, rb2),
                stiffness_time: self.config.stiffness_time,
            },
        );
        *m.friction = rec.limit;
        if out.target != [0.0; 2] {
            let v = basis.lift(out.target);
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity += v;
            }
        }
    }
}
