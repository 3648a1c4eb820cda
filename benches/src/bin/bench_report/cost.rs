//! The cost section: criterion's step times and the bench's extra pass, as ratios against plain
//! rapier, with the targets.

use crate::Options;
use crate::table::{self, Summary, int, num, ratio, render};
use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;

/// Target (issue 27): EP's step time over plain rapier's in scenes at rest, where stickslip
/// lets quiet contacts recycle as plain rapier does.
const REST_TARGET: f64 = 1.10;
/// Target (issue 27): EP's step time over plain rapier's in active scenes (sliding, tumbling,
/// driven), where rapier recycles little and stickslip's hook runs on most contacts.
const ACTIVE_PLAIN_TARGET: f64 = 1.25;
/// Target (issue 38): EP's step time over the no-op hook on the same colliders in active
/// scenes (stickslip's own per-contact work).
const ACTIVE_HOOK_TARGET: f64 = 1.05;
/// Target (issue 27): the step time of EP with a vibration source over the no-op hook.
const TIME_TARGET: f64 = 1.10;
/// Scenes at rest (by name prefix): stacks, heaps and rows that stand still once settled.
const RESTING: [&str; 6] = [
    "plane_",
    "pile_",
    "towers_",
    "compounds_",
    "dominoes_",
    "keva_",
];

fn is_resting(scene: &str) -> bool {
    RESTING.iter().any(|p| scene.starts_with(p))
}
/// The variants that carry the step-time target (EP, and EP with vibration in either mode).
const TIMED_VARIANTS: [&str; 3] = ["ep", "ep_vib_resolved", "ep_vib_averaged"];
/// Target: how far stickslip's own cost per contact (EP − no-op hook) may move from 1k to
/// 100k contacts, as a share of plain rapier's cost per contact in the smallest world. (Its
/// own max/min spread means nothing once that cost is near zero, or below zero where
/// recycling makes EP cheaper than the hook.)
const FLAT_TARGET: f64 = 0.20;
/// Target: bytes of friction state per active contact.
const BYTES_TARGET: f64 = 64.0;

/// One plane size: (contact points, plain, no-op hook, EP ns per contact point).
type Scaling = (usize, f64, f64, f64);

/// The floor (no-op hook) over plain rapier, per scene.
type Floor = (String, f64);

/// Criterion's median (ns) and its 95 % interval for `group/function`.
fn criterion_median(dir: &Path, group: &str, function: &str) -> Option<(f64, f64, f64)> {
    let path = dir
        .join(group)
        .join(function)
        .join("new")
        .join("estimates.json");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    let m = &v["median"];
    Some((
        m["point_estimate"].as_f64()?,
        m["confidence_interval"]["lower_bound"].as_f64()?,
        m["confidence_interval"]["upper_bound"].as_f64()?,
    ))
}

struct Row<'a> {
    v: &'a Value,
    name: &'a str,
    criterion: Option<(f64, f64, f64)>,
    paired: f64,
}

impl Row<'_> {
    fn f(&self, key: &str) -> f64 {
        self.v[key].as_f64().unwrap_or(f64::NAN)
    }
}

fn us(ns: f64) -> String {
    num(ns / 1e3, 3)
}

pub fn section(md: &mut String, summary: &mut Summary, opts: &Options) -> Result<(), String> {
    let path = opts
        .cost_json
        .as_ref()
        .ok_or("no --cost-json (run scripts/bench_report.sh)")?;
    let doc: Value = serde_json::from_str(
        &std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?,
    )
    .map_err(|e| format!("{}: {e}", path.display()))?;
    let crit_dir = opts.criterion.as_deref();
    let state_bytes = doc["state_bytes_per_contact"].as_f64().unwrap_or(f64::NAN);
    let scenes = doc["scenes"]
        .as_array()
        .ok_or("no scenes in the cost json")?;

    let _ = writeln!(
        md,
        "## Cost: step time against plain rapier\n\n\
         One `PhysicsWorld` step of the same scene, stepped by plain rapier friction \
         (`FrictionModel::Simplified`, rapier's 3D default and the model stickslip runs on, and \
         `FrictionModel::Coulomb`), by a hook that does nothing (rapier never recycles hooked \
         pairs, so this is the floor of any contact modifier), and by stickslip with each law and \
         with a normal vibration source (ratio 0.3) in either mode on the ground/trough. In the \
         first seven scenes every dynamic body has sleeping disabled; the five after rapier's \
         examples leave sleeping as the examples do, except the compound heap, the \
         dominoes and the keva tower, which would sleep before they are measured. Targets \
         (issues 27 and 38): in scenes at rest, EP ≤ 1.10× plain rapier; in active scenes, \
         ≤ 1.25× plain rapier and ≤ 1.05× the no-op hook; with a vibration source, ≤ 1.10× \
         the no-op hook.\n\n\
         Two timings of the same binary (`benches/benches/step_cost.rs`), both in **CPU time of the \
         stepping thread** (`CLOCK_THREAD_CPUTIME_ID`; steps are single-threaded, so on an idle \
         machine this is the wall time, and on this shared 2-core machine it leaves out the time \
         the thread waits for a core while other builds run):\n\
         - **criterion**: median of 20 samples per variant (1.5 s warm-up, 4 s measurement), \
         the variants one after the other;\n\
         - **paired**: all variants of a scene kept alive and stepped in 15 interleaved rounds \
         (rotating order); in each round a variant takes one untimed step (to warm its caches \
         after the others ran) and then ≈40 ms of timed steps (at least 2); median over \
         rounds. Load from other processes hits all variants alike, so the **paired ratios \
         are the ones the targets are judged on**; criterion's and the paired wall time are \
         shown beside them.\n\n\
         Contacts are counted after the measurement: manifolds (contact patches, the unit \
         stickslip keeps state for) and solver contact points (what rapier solves). \
         Allocations are counted by a counting `#[global_allocator]` in the bench binary over \
         50 steady-state steps.\n"
    );

    let mut worst_time: Vec<(String, f64)> = Vec::new();
    // (scene, EP ÷ plain, EP ÷ no-op hook), paired.
    let mut ep_time: Vec<(String, f64, f64)> = Vec::new();
    let mut floors: Vec<Floor> = Vec::new();
    let mut alloc_rows = Vec::new();
    let mut mem_rows = Vec::new();
    let mut worst_alloc: f64 = f64::NEG_INFINITY;
    let mut moving_alloc: Vec<String> = Vec::new();
    let mut plain_allocs: f64 = 0.0;
    let mut worst_bytes: f64 = 0.0;
    let mut worst_own: f64 = 0.0;
    let mut part_rows = Vec::new();
    let mut worst_state: f64 = 0.0;
    let mut scaling: Vec<Scaling> = Vec::new();

    for scene in scenes {
        let name = scene["name"].as_str().unwrap_or("?");
        let rows: Vec<Row> = scene["variants"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|v| {
                let vname = v["variant"].as_str().unwrap_or("?");
                Row {
                    v,
                    name: vname,
                    criterion: crit_dir.and_then(|d| criterion_median(d, name, vname)),
                    paired: v["paired_ns_per_step"].as_f64().unwrap_or(f64::NAN),
                }
            })
            .collect();
        let find = |n: &str| rows.iter().find(|r| r.name == n);
        let base = find("plain_simplified");
        let coul = find("plain_coulomb");
        let noop = find("noop_hook");
        let crit = |r: Option<&Row>| r.and_then(|r| r.criterion).map_or(f64::NAN, |c| c.0);
        let _ = writeln!(
            md,
            "### `{name}`: {}\n",
            scene["describe"].as_str().unwrap_or("")
        );
        let mut trs = Vec::new();
        for r in &rows {
            let is_ss = !matches!(r.name, "plain_simplified" | "plain_coulomb" | "noop_hook");
            let c = r.criterion.map_or(f64::NAN, |c| c.0);
            let paired_vs_base = r.paired / base.map_or(f64::NAN, |b| b.paired);
            let paired_vs_noop = r.paired / noop.map_or(f64::NAN, |b| b.paired);
            if r.name == "noop_hook" {
                floors.push((name.to_string(), paired_vs_base));
            }
            let target = if r.name == "ep" {
                ep_time.push((name.to_string(), paired_vs_base, paired_vs_noop));
                if is_resting(name) {
                    let met = paired_vs_base <= REST_TARGET;
                    format!("≤ {REST_TARGET:.2}× plain: {}", table::verdict(met))
                } else {
                    let met = paired_vs_base <= ACTIVE_PLAIN_TARGET
                        && paired_vs_noop <= ACTIVE_HOOK_TARGET;
                    format!(
                        "≤ {ACTIVE_PLAIN_TARGET:.2}× plain, ≤ {ACTIVE_HOOK_TARGET:.2}× no-op: {}",
                        table::verdict(met)
                    )
                }
            } else if is_ss && TIMED_VARIANTS.contains(&r.name) {
                let met = paired_vs_noop <= TIME_TARGET;
                worst_time.push((format!("{name} {}", r.name), paired_vs_noop));
                format!("≤ {TIME_TARGET:.2}× no-op: {}", table::verdict(met))
            } else {
                "—".into()
            };
            trs.push(vec![
                format!("`{}`", r.name),
                format!("{} / {}", int(r.f("manifolds")), int(r.f("points"))),
                r.criterion.map_or("—".into(), |(m, lo, hi)| {
                    format!("{} ({}–{})", us(m), us(lo), us(hi))
                }),
                ratio(c / crit(base)),
                ratio(c / crit(coul)),
                ratio(c / crit(noop)),
                us(r.paired),
                us(r.f("paired_wall_ns_per_step")),
                ratio(paired_vs_base),
                ratio(paired_vs_noop),
                target,
            ]);
            if !r.v["sane"].as_bool().unwrap_or(true) {
                let _ = writeln!(md, "- ⚠ `{}`: a body left the scene (blow-up)", r.name);
            }
        }
        md.push_str(&render(
            &[
                "variant",
                "manifolds / points",
                "criterion CPU µs/step (95 % CI)",
                "× plain Simplified",
                "× plain Coulomb",
                "× no-op hook",
                "paired CPU µs/step",
                "paired wall µs/step",
                "paired × plain Simplified",
                "paired × no-op hook",
                "target",
            ],
            &trs,
        ));

        // Allocations per step.
        let a = |n: &str| find(n).map_or(f64::NAN, |r| r.f("allocs_per_step"));
        let ep_extra = a("ep") - a("noop_hook");
        if name.starts_with("plane_") || name.starts_with("pile_") {
            plain_allocs = plain_allocs.max(a("plain_simplified"));
        }
        let ss_extra = rows
            .iter()
            .filter(|r| !matches!(r.name, "plain_simplified" | "plain_coulomb" | "noop_hook"))
            .map(|r| r.f("allocs_per_step") - a("noop_hook"))
            .fold(f64::NEG_INFINITY, f64::max);
        // Static scenes (nothing moves): rapier allocates the same in every variant, so the
        // difference is stickslip's. In moving scenes the worlds drift apart and rapier's own
        // per-step allocations differ between variants.
        if name.starts_with("plane_") || name.starts_with("pile_") {
            worst_alloc = worst_alloc.max(ss_extra);
        } else {
            moving_alloc.push(format!("`{name}` {}", num(ss_extra, 3)));
        }
        alloc_rows.push(vec![
            format!("`{name}`"),
            num(a("plain_simplified"), 3),
            num(a("plain_coulomb"), 3),
            num(a("noop_hook"), 3),
            num(a("ep"), 3),
            num(a("regul"), 3),
            num(a("phys"), 3),
            num(a("ep_vib_resolved"), 3),
            num(a("ep_vib_averaged"), 3),
            num(ep_extra, 3),
        ]);

        // Memory: live heap of the EP world minus plain rapier's in static scenes (both
        // recycle resting pairs, and rapier's recycling keeps state the no-op world, which
        // never recycles, does not), minus the no-op-hook world's elsewhere.
        let is_static = name.starts_with("plane_") || name.starts_with("pile_");
        let heap_base = if is_static { base } else { noop };
        if let (Some(ep), Some(nh)) = (find("ep"), heap_base) {
            let extra = ep.f("live_heap_bytes") - nh.f("live_heap_bytes");
            let manifolds = ep.f("manifolds");
            let points = ep.f("points");
            let records = ep.f("stickslip_active_contacts");
            let per_manifold = extra / manifolds;
            // stickslip's own count of its heap (every container it owns, capacity
            // included): in moving scenes the two worlds' contact sets drift apart, so the
            // heap difference there also holds rapier's.
            let own = ep.f("stickslip_heap_bytes") / manifolds;
            worst_own = worst_own.max(own);
            let part = |p: &str| {
                num(
                    ep.v["stickslip_heap_parts"][p].as_f64().unwrap_or(f64::NAN) / manifolds,
                    3,
                )
            };
            part_rows.push(vec![
                format!("`{name}`"),
                part("store"),
                part("recycling"),
                part("patches"),
                num(
                    (ep.f("stickslip_heap_bytes")
                        - ["store", "recycling", "patches"]
                            .iter()
                            .map(|p| {
                                ep.v["stickslip_heap_parts"][*p]
                                    .as_f64()
                                    .unwrap_or(f64::NAN)
                            })
                            .sum::<f64>())
                        / manifolds,
                    3,
                ),
                num(own, 3),
            ]);
            if name.starts_with("plane_") || name.starts_with("pile_") {
                worst_bytes = worst_bytes.max(per_manifold);
            }
            worst_state = worst_state.max(state_bytes * records / manifolds);
            mem_rows.push(vec![
                format!("`{name}`"),
                int(manifolds),
                int(points),
                int(ep.f("all_manifolds")),
                int(records),
                num(state_bytes * records / manifolds, 3),
                num(extra / 1024.0, 4),
                num(extra / records, 3),
                num(per_manifold, 3),
                num(extra / points, 3),
                num(own, 3),
                num(ep.f("live_heap_growth_per_step"), 3),
            ]);
        }

        // Scaling: planes.
        if let Some(n) = name
            .strip_prefix("plane_")
            .and_then(|s| s.parse::<usize>().ok())
            && let (Some(b), Some(nh), Some(ep)) = (base, noop, find("ep"))
        {
            let pts = ep.f("points");
            let _ = n;
            scaling.push((
                pts as usize,
                b.paired / pts,
                nh.paired / pts,
                ep.paired / pts,
            ));
        }
    }

    // Targets: step time against plain rapier (and, where contacts are active, the floor).
    for (scene, plain, noop) in &ep_time {
        if is_resting(scene) {
            summary.add(
                format!("step time, EP, `{scene}` (at rest)"),
                &format!("≤ {REST_TARGET}× plain rapier"),
                format!("{} plain ({} no-op)", ratio(*plain), ratio(*noop)),
                *plain <= REST_TARGET,
            );
        } else {
            summary.add(
                format!("step time, EP, `{scene}` (active)"),
                &format!(
                    "≤ {ACTIVE_PLAIN_TARGET}× plain rapier, ≤ {ACTIVE_HOOK_TARGET}× no-op hook"
                ),
                format!("{} plain, {} no-op", ratio(*plain), ratio(*noop)),
                *plain <= ACTIVE_PLAIN_TARGET && *noop <= ACTIVE_HOOK_TARGET,
            );
        }
    }
    if let Some((what, r)) = worst_time
        .iter()
        .filter(|(w, _)| !w.ends_with(" ep"))
        .max_by(|a, b| a.1.total_cmp(&b.1))
    {
        summary.add(
            "step time, EP with vibration (either mode), worst scene",
            &format!("≤ {TIME_TARGET}× no-op hook"),
            format!("{} (`{what}`)", ratio(*r)),
            *r <= TIME_TARGET,
        );
    }
    summary.info(
        "the floor itself: no-op hook over plain rapier (Simplified)",
        "—",
        floors
            .iter()
            .map(|(n, r)| format!("`{n}` {}", ratio(*r)))
            .collect::<Vec<_>>()
            .join(", "),
    );

    // Scaling table.
    let _ = writeln!(
        md,
        "### Cost per contact from 1k to 100k contacts (boxes on a plane, paired CPU time)\n"
    );
    scaling.sort_by_key(|s| s.0);
    if scaling.len() >= 2 {
        let rows: Vec<Vec<String>> = scaling
            .iter()
            .map(|(p, b, nh, ep)| {
                vec![
                    int(*p as f64),
                    num(*b, 3),
                    num(*nh, 3),
                    num(*ep, 3),
                    num(ep - b, 3),
                    num(ep - nh, 3),
                ]
            })
            .collect();
        md.push_str(&render(
            &[
                "contact points",
                "plain ns/contact",
                "no-op hook ns/contact",
                "EP ns/contact",
                "EP − plain ns/contact",
                "EP − no-op (stickslip's own) ns/contact",
            ],
            &rows,
        ));
        let spread = |f: &dyn Fn(&Scaling) -> f64| {
            let v: Vec<f64> = scaling.iter().map(f).collect();
            let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
            let hi = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            hi / lo - 1.0
        };
        let ep_spread = spread(&|s| s.3);
        let plain_spread = spread(&|s| s.1);
        // stickslip's own part: how far it moves over the sizes, in ns per contact and as a
        // share of plain rapier's cost per contact in the smallest world.
        let own: Vec<f64> = scaling.iter().map(|s| s.3 - s.2).collect();
        let own_lo = own.iter().cloned().fold(f64::INFINITY, f64::min);
        let own_hi = own.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let own_moves = own_hi - own_lo;
        let plain_first = scaling.first().map_or(f64::NAN, |s| s.1);
        let own_share = own_moves / plain_first;
        let range = format!(
            "{}–{} points",
            scaling.first().map_or(0, |s| s.0),
            scaling.last().map_or(0, |s| s.0)
        );
        let first_points = scaling.first().map_or(0, |s| s.0);
        let _ = writeln!(
            md,
            "Spread of the cost per contact (max/min − 1) over {range}: EP {}, plain rapier {}. \
             stickslip's own part (EP − no-op hook) moves by {} ns per contact over them \
             ({} to {} ns), {} of plain rapier's {} ns per contact at {first_points} points.\n",
            table::upct(ep_spread),
            table::upct(plain_spread),
            num(own_moves, 3),
            num(own_lo, 3),
            num(own_hi, 3),
            table::upct(own_share),
            num(plain_first, 3),
        );
        let full = scaling.last().is_some_and(|s| s.0 >= 50_000);
        summary.add(
            format!("stickslip's own cost per contact (EP − no-op) flat, {range}"),
            "moves by ≤ 20 % of plain rapier's cost per contact",
            format!(
                "moves by {} ({} ns; EP spread {}, plain rapier {}){}",
                table::upct(own_share),
                num(own_moves, 3),
                table::upct(ep_spread),
                table::upct(plain_spread),
                if full { "" } else { "; 100k not run" }
            ),
            own_share <= FLAT_TARGET && full,
        );
    } else {
        md.push_str("Not measured (needs the plane scenes).\n\n");
    }

    // Memory.
    let _ = writeln!(
        md,
        "### Memory per active contact\n\n\
         stickslip keeps one record per contact manifold (a patch of up to 4 points under \
         rapier's `Simplified` friction, which solves one friction constraint per manifold): \
         `StickSlip::STATE_BYTES_PER_CONTACT` = **{state_bytes} bytes** (law state, mean \
         normal force, bookkeeping), i.e. {} bytes per solver contact point on a box face. \
         The slot packs the record without padding: f32 law state, the colliders by arena \
         index on 24 bits each, the last slip speed as a bfloat16, liveness, sweep parity, \
         regime and generation in one 16-bit word, and a one-byte lock. The store sweeps the \
         records of vanished contacts every 8 steps, or as soon as it has created 1/16 of its \
         slots since the last sweep (contacts that come and go). stickslip's own count \
         (`StickSlip::heap_bytes`) adds up every container the modifier owns at its allocated \
         capacity, in every scene (the target's measure; the parts are in the second table). \
         Measured besides, as a check from outside: the live heap of the EP world minus \
         plain rapier's world of the same scene in the static scenes (`plane`, `pile`: both \
         recycle their resting pairs), the no-op-hook world's in the others (both built and \
         settled the same way; in moving scenes the two worlds drift apart, and the \
         difference holds rapier's own heap too), which \
         adds the slot array's spare capacity (it grows by 1/32, at least 16 slots, and shrinks \
         back after churn), \
         the key map (at steady state only rapier's merged cluster manifolds, whose \
         `user_data` rapier resets), the free list, the hook-flag bit sets, and the pose of \
         each quiet collider (23 B: where its drift is measured from). Per-contact \
         reports are opt-in (`ReadBack::Contacts`, ~100 B a contact) and not on here: the \
         benches run `StickSlip::new` as a user would.\n",
        num(state_bytes / 4.0, 3)
    );
    md.push_str(&render(
        &[
            "scene",
            "active manifolds",
            "solver points",
            "all manifolds rapier keeps",
            "stickslip records",
            "record B per active manifold",
            "stickslip heap KiB",
            "heap B per record",
            "heap B per active manifold",
            "heap B per point",
            "stickslip's own count, B per active manifold",
            "heap growth B/step",
        ],
        &mem_rows,
    ));
    let _ = writeln!(
        md,
        "\"Active manifolds\" have at least one solver contact point. rapier also keeps \
         manifolds whose points all lie beyond the contact prediction distance (pairs whose \
         enlarged bounding boxes overlap: neighbouring stacks, parts side by side, where \
         dynamic bodies are hooked (`pile`, `trough`)); stickslip keeps no record for those \
         (unless a wrapped hook stores a `user_data` value there).\n"
    );
    let _ = writeln!(
        md,
        "stickslip's own count by part (`StickSlip::heap_parts`), B per active manifold: the \
         contact store (slots with their spare capacity, key map, free list), recycling (the \
         quiet colliders' poses, 23 B a collider, and the per-collider bit sets), the contact \
         patches of composite shapes measured after each solve (a 32-byte entry a patch, and \
         the patches the hook saw), and the rest (attached colliders, materials, vibration \
         sources, rolling resistance, reports).\n"
    );
    md.push_str(&render(
        &[
            "scene",
            "store",
            "recycling",
            "patches",
            "rest",
            "all (own count)",
        ],
        &part_rows,
    ));
    summary.add(
        "friction state per active contact (records kept × record size / active manifolds)",
        "≤ 64 B",
        format!("{} B, worst scene", num(worst_state, 3)),
        worst_state <= BYTES_TARGET,
    );
    summary.add(
        "all stickslip heap per active contact (slots, spare capacity, key map, free list, \
         flags): live heap EP − plain rapier, static scenes",
        "≤ 64 B",
        format!("{} B per active manifold, worst scene", num(worst_bytes, 3)),
        worst_bytes <= BYTES_TARGET,
    );
    summary.add(
        "all stickslip heap per active contact by its own count (every container it owns, \
         capacity included), every scene",
        "≤ 64 B",
        format!("{} B per active manifold, worst scene", num(worst_own, 3)),
        worst_own <= BYTES_TARGET,
    );

    // Allocations.
    let _ = writeln!(
        md,
        "### Heap allocations per step in steady state\n\n\
         The last column is what stickslip adds: EP minus the no-op hook in the same scene \
         (rapier's own allocations per step are in the first columns).\n"
    );
    md.push_str(&render(
        &[
            "scene",
            "plain Simplified",
            "plain Coulomb",
            "no-op hook",
            "EP",
            "Regul",
            "Phys",
            "EP + resolved vib.",
            "EP + averaged vib.",
            "EP − no-op",
        ],
        &alloc_rows,
    ));
    let _ = writeln!(
        md,
        "In the static scenes (`plane`, `pile`: nothing moves) rapier allocates the same in \
         every variant, so any difference would be stickslip's. The moving scenes (`chain`, \
         `trough`) drift apart between variants (different contact sets step by step), so \
         rapier's own count differs there; worst stickslip variant over the no-op hook: {}.\n",
        moving_alloc.join(", ")
    );
    summary.add(
        "heap allocations per step added by stickslip (steady state, static scenes)",
        "0",
        format!(
            "{} (worst stickslip variant over the no-op hook; rapier itself: {} per step)",
            num(worst_alloc, 3),
            num(plain_allocs, 3)
        ),
        worst_alloc <= 0.0,
    );
    Ok(())
}

/// Thread scaling with rapier's `parallel` feature: speed-up from 1 to all threads of plain
/// rapier, the no-op hook and EP (from the bench's `STICKSLIP_BENCH_THREADS_OUT` pass).
pub fn threads_section(md: &mut String, summary: &mut Summary, opts: &Options) {
    let _ = writeln!(
        md,
        "### Thread scaling (rapier's `parallel` feature)\n\n\
         The same scenes built with `--features parallel` (rapier's narrow phase, and with it \
         the contact hook, runs on rayon's threads), each step run on a rayon pool of 1 thread \
         and of all threads, variants and pools interleaved over 9 rounds of 20 steps, median \
         wall time per step.\n"
    );
    let doc = opts
        .threads_json
        .as_ref()
        .and_then(|p| serde_json::from_str::<Value>(&std::fs::read_to_string(p).ok()?).ok());
    let Some(doc) = doc else {
        md.push_str("Not measured (no `--threads-json`; run `scripts/bench_report.sh`).\n\n");
        summary.add(
            "hook scales with threads as rapier does",
            "EP speed-up ≈ plain rapier's",
            "not measured".to_string(),
            false,
        );
        return;
    };
    let mut rows = Vec::new();
    let mut worst: Option<(String, f64, f64)> = None;
    for scene in doc["scenes"].as_array().into_iter().flatten() {
        let name = scene["name"].as_str().unwrap_or("?");
        let find = |v: &str| {
            scene["variants"]
                .as_array()
                .into_iter()
                .flatten()
                .find(|r| r["variant"] == v)
                .cloned()
        };
        let speed = |v: &str| {
            find(v)
                .and_then(|r| r["speedup"].as_f64())
                .unwrap_or(f64::NAN)
        };
        for v in ["plain_simplified", "noop_hook", "ep"] {
            if let Some(r) = find(v) {
                let w: Vec<f64> = r["wall_ns_per_step"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .filter_map(|x| x.as_f64())
                    .collect();
                let threads: Vec<String> = r["threads"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(|x| x.to_string())
                    .collect();
                rows.push(vec![
                    format!("`{name}`"),
                    format!("`{v}`"),
                    threads.join(" → "),
                    w.iter().map(|x| us(*x)).collect::<Vec<_>>().join(" → "),
                    ratio(speed(v)),
                ]);
            }
        }
        let (plain, ep) = (speed("plain_simplified"), speed("ep"));
        if worst.as_ref().is_none_or(|w| ep / plain < w.2 / w.1) {
            worst = Some((name.to_string(), plain, ep));
        }
    }
    md.push_str(&render(
        &["scene", "variant", "threads", "wall µs/step", "speed-up"],
        &rows,
    ));
    if let Some((name, plain, ep)) = worst {
        summary.add(
            "hook scales with threads as rapier does (2 cores)",
            "EP speed-up ≥ 0.9× plain rapier's",
            format!(
                "EP {} vs plain {} (`{name}`, the worse scene)",
                ratio(ep),
                ratio(plain)
            ),
            ep >= 0.9 * plain,
        );
    }
}
