//! The integration tests, one binary with a module per behaviour (as
//! resvg's `tests/integration`): each module links the library once, and
//! its tests run side by side with every other module's. `common` holds
//! the helpers (tools' presence, temporary folders, goldens, decoders).
//!
//! The two tests that count the heap's allocations (`tests/alloc.rs`,
//! `tests/memory_caps.rs`) stay binaries of their own: a counting global
//! allocator would count every other test's allocations too. So does
//! `tests/temp_cleanup.rs`: it leaves its process unable to write.

mod common;

mod arrivals;
mod article_revtex;
mod auto_acceptance;
mod auto_window;
mod batch;
mod bench;
mod bench_tank;
mod caps;
mod captions;
mod chain_verlet;
mod cli;
mod cluster_recipe;
mod cost_model;
mod data_files;
mod decisions;
mod docs_and_packaging;
mod energies;
mod energy_view;
mod experiment_figures;
mod experiment_movies;
mod experiments;
mod figure_words;
mod figures;
mod filmstrips;
mod formats;
mod gallery;
mod golden;
mod hanging_start;
mod hostile;
mod inextensible;
mod italic;
mod kernels;
mod messages;
mod mp4_quality;
mod names;
mod npz;
mod outcome_reports;
mod output_paths;
mod panel_labels;
mod parameter_table;
mod print;
mod print_article;
mod print_property;
mod provenance;
mod reliability;
mod render;
mod ribbons;
mod rings;
mod rings_alternate;
mod rings_captions;
mod rings_modes;
mod rings_settle;
mod rings_tumbling;
mod scene_files;
mod scene_fuzz;
mod scenes;
mod scenes_accuracy;
mod shard_fuzz;
mod shared_runs;
mod sim;
mod sources;
mod state_consistency;
mod stop_rules;
mod strap;
mod sweep;
mod sweep_caps;
mod theory;
mod theory_data;
mod timings;
mod toy;
mod toy_pictures;
mod waves;
mod write_failures;
