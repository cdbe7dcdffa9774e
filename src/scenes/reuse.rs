//! The store of the runs a render shares between its outputs
//! (`scenes::shared` plans and makes them): each run by the key of
//! everything that decides it ([`key`]), what it gave, how many runs it
//! took and the output it was charged to; [`or_run`] takes a run from it
//! where a render holds it. Nothing is kept on disk, and nothing after
//! the render that made it (`Held` gives its runs back when dropped).

use crate::scene::Scene;
use crate::sim::tally::{self, Tally};
use std::any::Any;
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// What ends a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Stop {
    /// Nothing before its t_end (`sim::run_to_end`): `run::simulate`.
    ToEnd,
    /// An experiment figure's rule (`experiments` decided): once the run
    /// has decided what it was run for.
    Decided,
}

/// Everything that decides a run of `scene` sampled at `samples` and
/// ended by `stop`, as one string: the Debug text of the scene's model,
/// drive, run (window, integrator, step, tolerance), apparatus, ring
/// chain and caps (Rust writes every f64 so that it reads back to the
/// same bits), the samples' bits (a step lands on every sample time but
/// where blocks touch, so other samples give other steps and other bits)
/// and the stop
/// rule. The scene is taken apart field by field, so that a field added
/// to `Scene` must be placed here (in the key, or among the words and
/// pictures that no run reads) before the program compiles.
pub fn key(scene: &Scene, samples: &[f64], stop: Stop) -> String {
    let Scene {
        // Words and pictures: no run reads them (`Scene::scenario`).
        name: _,
        label: _,
        title: _,
        caption: _,
        output: _,
        style: _,
        model,
        drive,
        run,
        apparatus,
        rings,
        limits,
    } = scene;
    let bits: Vec<u64> = samples.iter().map(|t| t.to_bits()).collect();
    format!("{stop:?}|{model:?}|{drive:?}|{run:?}|{apparatus:?}|{rings:?}|{limits:?}|{bits:?}")
}

/// A shared run: what it gave, the runs it took to make (an automatic
/// step's pair and halvings) and the tally of the output it was charged
/// to.
pub struct Entry {
    pub made: Arc<dyn Any + Send + Sync>,
    pub runs: u64,
    pub owner: Arc<Tally>,
}

/// The shared runs of every render under way, by [`key`].
static STORE: Mutex<Option<HashMap<String, Arc<Entry>>>> = Mutex::new(None);
/// How many runs [`STORE`] holds: none (the common case) costs no key.
static HELD: AtomicUsize = AtomicUsize::new(0);

fn store() -> std::sync::MutexGuard<'static, Option<HashMap<String, Arc<Entry>>>> {
    STORE.lock().unwrap_or_else(|e| e.into_inner())
}

/// Runs a render holds in the store while this lives.
pub struct Held {
    keys: Vec<String>,
}

impl Held {
    /// Holds `made` (by key) until the returned value is dropped.
    pub fn hold(made: Vec<(String, Entry)>) -> Self {
        let keys = made.iter().map(|(k, _)| k.clone()).collect();
        let mut store = store();
        let map = store.get_or_insert_with(HashMap::new);
        for (k, e) in made {
            if map.insert(k, Arc::new(e)).is_none() {
                HELD.fetch_add(1, Ordering::Relaxed);
            }
        }
        Self { keys }
    }

    /// How many runs are held.
    pub fn len(&self) -> usize {
        self.keys.len()
    }

    /// Whether none is.
    pub fn is_empty(&self) -> bool {
        self.keys.is_empty()
    }
}

impl Drop for Held {
    fn drop(&mut self) {
        let mut store = store();
        if let Some(map) = store.as_mut() {
            for k in &self.keys {
                if map.remove(k).is_some() {
                    HELD.fetch_sub(1, Ordering::Relaxed);
                }
            }
        }
    }
}

/// The run of `scene` at `samples` ended by `stop`: the one a render
/// holds (counted as reused by an output other than the one it was made
/// for), else `make()`.
pub fn or_run<T: Clone + 'static>(
    scene: &Scene,
    samples: &[f64],
    stop: Stop,
    make: impl FnOnce() -> crate::error::Result<T>,
) -> crate::error::Result<T> {
    if HELD.load(Ordering::Relaxed) == 0 {
        return make();
    }
    let k = key(scene, samples, stop);
    let held = store().as_ref().and_then(|m| m.get(&k).cloned());
    let Some((entry, made)) = held.and_then(|e| {
        let made = e.made.downcast_ref::<T>()?.clone();
        Some((e, made))
    }) else {
        return make();
    };
    let mine = tally::current().is_some_and(|t| Arc::ptr_eq(&t, &entry.owner));
    if !mine {
        tally::record_reused(entry.runs);
    }
    Ok(made)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog;
    use crate::scene::Kind;

    fn movie(id: &str) -> Scene {
        catalog::find(Kind::Movie, id).unwrap().scene.clone()
    }

    /// Movies 3 and 4 differ in their name, caption and camera only: one
    /// run. Each thing that decides a run makes another key.
    #[test]
    fn the_key_is_what_decides_the_run() {
        let (m3, m4) = (movie("3"), movie("4"));
        let times = [0.0, 10.0, 2200.0];
        let k = |s: &Scene, t: &[f64], stop| key(s, t, stop);
        assert_eq!(k(&m3, &times, Stop::ToEnd), k(&m4, &times, Stop::ToEnd));
        let base = k(&m4, &times, Stop::ToEnd);
        let mut changed: Vec<String> = vec![
            k(&m4, &times, Stop::Decided),
            k(&m4, &[0.0, 10.0, 2199.0], Stop::ToEnd),
            k(&m4, &times[..2], Stop::ToEnd),
        ];
        let mut other = |change: &dyn Fn(&mut Scene)| {
            let mut s = m4.clone();
            change(&mut s);
            changed.push(k(&s, &times, Stop::ToEnd));
        };
        other(&|s| s.model.alpha = 60.000_000_000_001);
        other(&|s| s.model.n = 11);
        other(&|s| s.run.t_end = 2100.0);
        other(&|s| s.run.dt = Some(0.25));
        other(&|s| s.run.tolerance *= 0.5);
        other(&|s| s.drive = movie("11").drive.clone());
        other(&|s| s.apparatus = movie("water-tank").apparatus.clone());
        other(&|s| s.limits.block_steps *= 0.5);
        for c in &changed {
            assert_ne!(*c, base);
        }
    }

    /// A held run is taken (and counted as reused by another output's
    /// tally); given back, the run is made again.
    #[test]
    fn a_held_run_is_taken_until_it_is_given_back() {
        let mut s = movie("4");
        s.model.alpha = 61.234_567;
        let owner = Arc::new(Tally::default());
        let other = Arc::new(Tally::default());
        let entry = Entry {
            made: Arc::new(7u32),
            runs: 2,
            owner: owner.clone(),
        };
        let held = Held::hold(vec![(key(&s, &[1.0], Stop::ToEnd), entry)]);
        assert_eq!(held.len(), 1);
        let take = |stop| or_run(&s, &[1.0], stop, || Ok(9u32)).unwrap();
        tally::within(Some(other.clone()), || {
            assert_eq!(take(Stop::ToEnd), 7);
            assert_eq!(take(Stop::Decided), 9, "another key is made");
        });
        tally::within(Some(owner.clone()), || assert_eq!(take(Stop::ToEnd), 7));
        assert_eq!((other.reused(), owner.reused()), (2, 0));
        drop(held);
        assert_eq!(take(Stop::ToEnd), 9);
    }
}
