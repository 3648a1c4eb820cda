//! Step cost of stickslip against plain rapier friction, in the same run.
//!
//! Measures, for each scene of `benches/common` (boxes on a plane at ≈1k and ≈10k contact
//! points, a 4-high pile at ≈10k, a 250-contact chain driven at 50 Hz, a vibratory trough with
//! 480 parts, 3 × 3 plank towers of 432 planks, 400 rolling balls; after rapier's examples, a
//! drum of 1000 tumbling cubes, 384 bodies on a heightfield, 256 compounds, 216 boxes on
//! swinging platforms, 1000 dominoes; a plane at ≈100k points with `STICKSLIP_BENCH_FULL=1`):
//! - criterion (thread CPU time, see [`ThreadCpu`]): one `PhysicsWorld` step with plain rapier (`FrictionModel::Simplified`
//!   and `::Coulomb`), a no-op contact hook, and stickslip with EP, Regul, Phys, and EP with a
//!   time-resolved and an averaged vibration source (the rolling balls also with EP and
//!   rolling and spinning resistance, `ep_rolling`);
//! - an extra pass, outside criterion's timing, with a counting `#[global_allocator]`: contacts
//!   really active (manifolds and points), heap allocations per step in steady state, live heap
//!   bytes of each world (stickslip's state = EP world − no-op-hook world), and step times
//!   measured interleaved (round-robin over the variants, one untimed warm-up step then
//!   ≈40 ms of timed steps per turn, median of rounds; thread CPU time and wall time), which
//!   cancels drifts of machine load between variants.
//!
//! Full run: `STICKSLIP_BENCH_OUT=cost.json cargo bench -p stickslip-benches --bench step_cost` (the report script
//! does this). Smoke run (each bench once, small settle, tiny extra pass):
//! `cargo test -p stickslip-benches --benches` or `cargo bench -p stickslip-benches --bench
//! step_cost -- --test`. One variant alone, for a profiler:
//! `STICKSLIP_BENCH_PROBE=pile_10000/ep/500 <bench binary> --bench` (see `probe`).

mod common;

use common::{Bench, Scene, Variant};
use criterion::measurement::{Measurement, ValueFormatter, WallTime};
use criterion::{BenchmarkId, Criterion, SamplingMode};
use serde_json::{Value, json};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicI64, AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};
use stickslip::rapier::StickSlip;

/// Counts every allocation and tracks the live heap bytes.
struct Counting;

static ALLOCS: AtomicU64 = AtomicU64::new(0);
static ALLOC_BYTES: AtomicU64 = AtomicU64::new(0);
static LIVE: AtomicI64 = AtomicI64::new(0);

// SAFETY: forwards to the system allocator unchanged; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Relaxed);
        ALLOC_BYTES.fetch_add(layout.size() as u64, Relaxed);
        LIVE.fetch_add(layout.size() as i64, Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Relaxed);
        ALLOC_BYTES.fetch_add(layout.size() as u64, Relaxed);
        LIVE.fetch_add(layout.size() as i64, Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size() as i64, Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCS.fetch_add(1, Relaxed);
        ALLOC_BYTES.fetch_add(new_size as u64, Relaxed);
        LIVE.fetch_add(new_size as i64 - layout.size() as i64, Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// CPU time consumed by the calling thread.
fn thread_cpu() -> Duration {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec; the clock id is a constant of the platform.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    if rc != 0 {
        return Duration::ZERO;
    }
    Duration::new(ts.tv_sec as u64, ts.tv_nsec as u32)
}

/// Criterion measurement: CPU time of the benchmarking thread. Steps are single-threaded
/// (rapier without its `parallel` feature), so on an idle machine this equals wall time, and
/// on a busy one (2 cores shared with builds) it leaves out the time the thread waits to be
/// scheduled, which is what makes wall-clock ratios between variants drift.
struct ThreadCpu;

static WALL: WallTime = WallTime;

impl Measurement for ThreadCpu {
    type Intermediate = Duration;
    type Value = Duration;
    fn start(&self) -> Duration {
        thread_cpu()
    }
    fn end(&self, i: Duration) -> Duration {
        thread_cpu().saturating_sub(i)
    }
    fn add(&self, v1: &Duration, v2: &Duration) -> Duration {
        *v1 + *v2
    }
    fn zero(&self) -> Duration {
        Duration::ZERO
    }
    fn to_f64(&self, val: &Duration) -> f64 {
        val.as_nanos() as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        WALL.formatter()
    }
}

/// How much to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    /// `cargo test --benches` / `-- --test`: every bench once, tiny extra pass.
    Smoke,
    /// `cargo bench`: the 1k/10k scenes.
    Normal,
    /// `STICKSLIP_BENCH_FULL=1`: also the ≈100k-point plane.
    Full,
}

fn mode() -> Mode {
    let args: Vec<String> = std::env::args().collect();
    let benching = args.iter().any(|a| a == "--bench") && !args.iter().any(|a| a == "--test");
    if !benching || std::env::var_os("STICKSLIP_BENCH_SMOKE").is_some() {
        Mode::Smoke
    } else if std::env::var_os("STICKSLIP_BENCH_FULL").is_some() {
        Mode::Full
    } else {
        Mode::Normal
    }
}

/// A positional filter (criterion's), applied to scene names in the extra pass too.
fn filter() -> Option<String> {
    let mut args = std::env::args().skip(1);
    let mut out = None;
    while let Some(a) = args.next() {
        if a.starts_with("--") {
            // Options with a value.
            if matches!(
                a.as_str(),
                "--save-baseline" | "--baseline" | "--load-baseline" | "--profile-time"
            ) {
                args.next();
            }
            continue;
        }
        out = Some(a);
    }
    out
}

fn scenes(mode: Mode) -> Vec<(Scene, &'static [Variant])> {
    const SCALING: &[Variant] = &[Variant::PlainSimplified, Variant::NoopHook, Variant::Ep];
    // The rolling balls also with rolling and spinning resistance (issue 41's cost).
    const ROLLING: &[Variant] = &[
        Variant::PlainSimplified,
        Variant::PlainCoulomb,
        Variant::NoopHook,
        Variant::Ep,
        Variant::Regul,
        Variant::Phys,
        Variant::EpVibResolved,
        Variant::EpVibAveraged,
        Variant::EpRolling,
    ];
    let mut v: Vec<(Scene, &'static [Variant])> = vec![
        (Scene::plane_for_points(1_000), &Variant::ALL),
        (Scene::plane_for_points(10_000), &Variant::ALL),
        (
            Scene::Pile {
                stacks: 625,
                height: 4,
            },
            &Variant::ALL,
        ),
        (Scene::Chain { links: 250 }, &Variant::ALL),
        (Scene::Trough { parts: 480 }, &Variant::ALL),
        (
            Scene::Towers {
                grid: 3,
                layers: 12,
            },
            &Variant::ALL,
        ),
        (Scene::Rolling { balls: 400 }, ROLLING),
        (Scene::Drum { cubes: 1000 }, SCALING),
        (Scene::Heightfield { bodies: 384 }, SCALING),
        (Scene::Compounds { bodies: 256 }, SCALING),
        (Scene::Platforms { boxes: 216 }, SCALING),
        (Scene::Dominoes { count: 1000 }, SCALING),
        (Scene::Keva, SCALING),
    ];
    if mode == Mode::Full {
        v.push((Scene::plane_for_points(100_000), SCALING));
    }
    v
}

fn settle_steps(scene: Scene, mode: Mode) -> usize {
    if mode == Mode::Smoke {
        3
    } else {
        scene.settle_steps()
    }
}

fn selected(scene: Scene, filter: &Option<String>) -> bool {
    filter.as_ref().is_none_or(|f| scene.name().contains(f))
}

fn run_criterion(mode: Mode, filter: &Option<String>) {
    let mut c = Criterion::default()
        .with_measurement(ThreadCpu)
        .warm_up_time(Duration::from_millis(1500))
        .measurement_time(Duration::from_secs(4))
        .sample_size(20)
        .without_plots()
        .configure_from_args();
    for (scene, variants) in scenes(mode) {
        if !selected(scene, filter) {
            continue;
        }
        let mut group = c.benchmark_group(scene.name());
        if matches!(scene, Scene::Plane { boxes } if boxes > 10_000) {
            group
                .sampling_mode(SamplingMode::Flat)
                .sample_size(10)
                .measurement_time(Duration::from_secs(8));
        }
        for &variant in variants {
            let mut bench = Bench::settled(scene, variant, settle_steps(scene, mode));
            group.bench_function(BenchmarkId::from_parameter(variant.name()), |b| {
                b.iter(|| bench.step())
            });
        }
        group.finish();
    }
    c.final_summary();
}

/// Live heap bytes, allocations and bytes allocated since the last call.
fn counters() -> (i64, u64, u64) {
    (
        LIVE.load(Relaxed),
        ALLOCS.load(Relaxed),
        ALLOC_BYTES.load(Relaxed),
    )
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    let n = v.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The extra pass for one scene.
fn extras(scene: Scene, variants: &[Variant], mode: Mode) -> Value {
    let settle = settle_steps(scene, mode);
    let alloc_steps = if mode == Mode::Smoke { 2 } else { 50 };
    let mut rows = Vec::new();
    let mut benches = Vec::new();
    for &variant in variants {
        // Live heap of the whole world (built and settled while nothing else allocates).
        let (live0, _, _) = counters();
        let mut b = Bench::settled(scene, variant, settle);
        let (live1, a0, ab0) = counters();
        for _ in 0..alloc_steps {
            b.step();
        }
        let (live2, a1, ab1) = counters();
        let (manifolds, points, all_manifolds) = b.contacts();
        let sane = b.is_sane();
        let active = b.modifier().map(|m| m.active_contacts());
        let capacity = b.modifier().map(|m| m.state_capacity());
        let state_heap = b.modifier().map(|m| m.state_heap_bytes());
        let heap = b.modifier().map(|m| m.heap_bytes());
        let heap_parts = b.modifier().map(|m| {
            m.heap_parts()
                .iter()
                .map(|&(part, bytes)| (part.to_string(), json!(bytes)))
                .collect::<serde_json::Map<_, _>>()
        });
        rows.push(json!({
            "variant": variant.name(),
            "manifolds": manifolds,
            "points": points,
            "all_manifolds": all_manifolds,
            "allocs_per_step": (a1 - a0) as f64 / alloc_steps as f64,
            "alloc_bytes_per_step": (ab1 - ab0) as f64 / alloc_steps as f64,
            "live_heap_bytes": live1 - live0,
            "live_heap_growth_per_step": (live2 - live1) as f64 / alloc_steps as f64,
            "stickslip_active_contacts": active,
            "stickslip_state_slots": capacity,
            "stickslip_state_heap_bytes": state_heap,
            "stickslip_heap_bytes": heap,
            "stickslip_heap_parts": heap_parts,
            "sane": sane,
        }));
        benches.push(b);
    }
    // Interleaved timing: rounds over all variants, rotating the order each round.
    let rounds = if mode == Mode::Smoke { 1 } else { 15 };
    let target = Duration::from_millis(if mode == Mode::Smoke { 1 } else { 40 });
    let block: Vec<usize> = benches
        .iter_mut()
        .map(|b| {
            let t = Instant::now();
            b.step();
            let one = t.elapsed().max(Duration::from_micros(1));
            (target.as_secs_f64() / one.as_secs_f64()).ceil().max(2.0) as usize
        })
        .collect();
    let mut cpu: Vec<Vec<f64>> = vec![Vec::new(); benches.len()];
    let mut wall: Vec<Vec<f64>> = vec![Vec::new(); benches.len()];
    for r in 0..rounds {
        for k in 0..benches.len() {
            let i = (k + r) % benches.len();
            // One untimed step: the other worlds just ran and evicted this one's caches.
            benches[i].step();
            let (c0, t) = (thread_cpu(), Instant::now());
            for _ in 0..block[i] {
                benches[i].step();
            }
            let n = block[i] as f64;
            wall[i].push(t.elapsed().as_secs_f64() * 1e9 / n);
            cpu[i].push((thread_cpu() - c0).as_secs_f64() * 1e9 / n);
        }
    }
    for ((row, c), w) in rows.iter_mut().zip(cpu.iter_mut()).zip(wall.iter_mut()) {
        row["paired_ns_per_step"] = json!(median(c));
        row["paired_wall_ns_per_step"] = json!(median(w));
    }
    json!({
        "name": scene.name(),
        "describe": scene.describe(),
        "dt": scene.dt(),
        "variants": rows,
    })
}

/// Thread scaling (built with rapier's `parallel` feature): wall time per step of plain
/// rapier, the no-op hook and EP with rapier's work on a rayon pool of 1 and of all threads.
/// Variants and pool sizes interleaved in rounds, median per cell.
#[cfg(feature = "parallel")]
fn thread_scaling(scene: Scene, mode: Mode) -> Value {
    let variants = [Variant::PlainSimplified, Variant::NoopHook, Variant::Ep];
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let pools: Vec<(usize, rayon::ThreadPool)> = [1, threads]
        .into_iter()
        .map(|n| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .expect("thread pool");
            (n, pool)
        })
        .collect();
    let settle = settle_steps(scene, mode);
    let mut benches: Vec<Bench> = variants
        .iter()
        .map(|&v| Bench::settled(scene, v, settle))
        .collect();
    let rounds = if mode == Mode::Smoke { 1 } else { 9 };
    let steps = if mode == Mode::Smoke { 1 } else { 20 };
    let mut wall = vec![vec![Vec::new(); pools.len()]; benches.len()];
    for r in 0..rounds {
        for (k, (_, pool)) in pools.iter().enumerate() {
            for i in 0..benches.len() {
                let i = (i + r) % benches.len();
                let b = &mut benches[i];
                pool.install(|| {
                    b.step();
                    let t = Instant::now();
                    for _ in 0..steps {
                        b.step();
                    }
                    wall[i][k].push(t.elapsed().as_secs_f64() * 1e9 / steps as f64);
                });
            }
        }
    }
    let rows: Vec<Value> = variants
        .iter()
        .zip(wall.iter_mut())
        .map(|(v, w)| {
            let per: Vec<f64> = w.iter_mut().map(|c| median(c)).collect();
            json!({
                "variant": v.name(),
                "threads": pools.iter().map(|p| p.0).collect::<Vec<_>>(),
                "wall_ns_per_step": per,
                "speedup": per[0] / per[per.len() - 1],
            })
        })
        .collect();
    json!({"name": scene.name(), "variants": rows})
}

/// `STICKSLIP_BENCH_PROBE=scene/variant/steps`: only step one variant of one scene (after
/// settling), for `perf stat` / `perf record` of a single variant; with
/// `STICKSLIP_BENCH_RECYCLE=0` rapier's contact recycling is off.
fn probe(spec: &str, mode: Mode) {
    let parts: Vec<&str> = spec.split('/').collect();
    let [scene_name, variant_name, steps] = parts[..] else {
        eprintln!("STICKSLIP_BENCH_PROBE=scene/variant/steps, got {spec}");
        return;
    };
    let steps: usize = steps.parse().unwrap_or(100);
    let mut all = scenes(Mode::Full);
    all.retain(|(s, _)| s.name() == scene_name);
    let Some(&(scene, variants)) = all.first() else {
        eprintln!("no scene {scene_name}");
        return;
    };
    let Some(&variant) = variants.iter().find(|v| v.name() == variant_name) else {
        eprintln!("no variant {variant_name}");
        return;
    };
    let mut b = Bench::settled(scene, variant, settle_steps(scene, mode));
    // STICKSLIP_BENCH_RECYCLE=0: rapier's contact recycling off (what a hooked pair never
    // gets: rapier skips it for every pair with active hooks).
    if std::env::var("STICKSLIP_BENCH_RECYCLE").is_ok_and(|v| v == "0") {
        b.world
            .integration_parameters
            .normalized_contact_recycle_distance = 0.0;
    }
    let mut phases = [Duration::ZERO; 3];
    let t = thread_cpu();
    for _ in 0..steps {
        for (sum, d) in phases.iter_mut().zip(b.step_phases(thread_cpu)) {
            *sum += d;
        }
    }
    let ns = (thread_cpu() - t).as_nanos() as f64 / steps as f64;
    let [before, rapier, after] = phases.map(|d| d.as_secs_f64() * 1e6 / steps as f64);
    let (pairs, touching) = b.pairs();
    let recycled = b.recycled().map_or(String::new(), |(q, n)| {
        format!(", {q} of {n} colliders recycled")
    });
    let (manifolds, _, _) = b.contacts();
    let records = b.modifier().map_or(String::new(), |m| {
        format!(
            ", {} records in {} slots ({} B by the store's count, {} B in all: {}) for \
             {manifolds} active manifolds",
            m.active_contacts(),
            m.state_capacity(),
            m.state_heap_bytes(),
            m.heap_bytes(),
            m.heap_parts()
                .iter()
                .filter(|(_, bytes)| *bytes > 0)
                .map(|(part, bytes)| format!("{part} {bytes}"))
                .collect::<Vec<_>>()
                .join(", ")
        )
    });
    // Whether the variant's world rests as another's does: awake dynamic bodies and their
    // mean speed at the end.
    let (awake, speed) = b
        .world
        .bodies
        .iter()
        .filter(|(_, rb)| rb.is_dynamic() && !rb.is_sleeping())
        .fold((0usize, 0.0f64), |(n, v), (_, rb)| {
            (n + 1, v + rb.linvel().length() as f64)
        });
    let mean_speed = if awake > 0 { speed / awake as f64 } else { 0.0 };
    println!(
        "{scene_name} {variant_name}: {ns:.0} ns/step over {steps} steps, {awake} bodies awake \
         (mean speed {mean_speed:.2e} m/s){recycled}{records}"
    );
    println!(
        "  per step (thread CPU µs): before rapier's step {before:.1}, rapier's step (hook \
         inside) {rapier:.1}, after it {after:.1}; {pairs} contact pairs, {touching} touching"
    );
}

fn main() {
    let mode = mode();
    let filter = filter();
    #[cfg(feature = "parallel")]
    if let Some(path) = std::env::var_os("STICKSLIP_BENCH_THREADS_OUT") {
        // Only the thread-scaling pass (the report script runs it as a second binary).
        let mut out = Vec::new();
        for scene in [
            Scene::plane_for_points(10_000),
            Scene::Pile {
                stacks: 625,
                height: 4,
            },
        ] {
            if !selected(scene, &filter) {
                continue;
            }
            let v = thread_scaling(scene, mode);
            println!("thread scaling {}: {v}", scene.name());
            out.push(v);
        }
        std::fs::write(
            &path,
            serde_json::to_string_pretty(&json!({"scenes": out})).expect("json"),
        )
        .expect("write STICKSLIP_BENCH_THREADS_OUT");
        return;
    }
    if let Ok(spec) = std::env::var("STICKSLIP_BENCH_PROBE") {
        probe(&spec, mode);
        return;
    }
    run_criterion(mode, &filter);

    let mut out = Vec::new();
    for (scene, variants) in scenes(mode) {
        if !selected(scene, &filter) {
            continue;
        }
        let started = Instant::now();
        let v = extras(scene, variants, mode);
        println!(
            "extra pass {}: {:.1} s",
            scene.name(),
            started.elapsed().as_secs_f64()
        );
        for r in v["variants"].as_array().into_iter().flatten() {
            println!(
                "  {:<18} {:>6} manifolds {:>7} points {:>9.1} allocs/step {:>12} live B \
                 ({} records, {} slots, {} state B, {} stickslip B) {:>12.0} ns/step (paired)",
                r["variant"].as_str().unwrap_or(""),
                r["manifolds"],
                r["points"],
                r["allocs_per_step"].as_f64().unwrap_or(f64::NAN),
                r["live_heap_bytes"],
                r["stickslip_active_contacts"],
                r["stickslip_state_slots"],
                r["stickslip_state_heap_bytes"],
                r["stickslip_heap_bytes"],
                r["paired_ns_per_step"].as_f64().unwrap_or(f64::NAN),
            );
        }
        out.push(v);
    }
    let doc = json!({
        "mode": format!("{mode:?}").to_lowercase(),
        "state_bytes_per_contact": StickSlip::<()>::STATE_BYTES_PER_CONTACT,
        "scenes": out,
    });
    if let Some(path) = std::env::var_os("STICKSLIP_BENCH_OUT") {
        std::fs::write(&path, serde_json::to_string_pretty(&doc).expect("json"))
            .expect("write STICKSLIP_BENCH_OUT");
        println!("wrote {}", path.to_string_lossy());
    }
}
