//! The flags made from the parameter table (`model::table`): one
//! `--NAME` per parameter, its value name, help (meaning, range and
//! default) and type (whole or real) the table's. `ParamFlags` are the
//! model's (`--alpha`, `--n`, ...), a value each; `GridFlags` every
//! parameter's sweep axis (`--alpha=-45:-60:-0.5`), a range or list.

use crate::scene::params::{Kind, Param};
use clap::{Arg, ArgMatches, Args, Command, FromArgMatches};

/// The model's flags as given: a value per model parameter, `None` where
/// the flag is left out (the base scene's value is kept).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ParamFlags(Vec<(Param, f64)>);

impl ParamFlags {
    /// Flags with these values (tests, and front ends that build them).
    pub fn of(values: &[(Param, f64)]) -> Self {
        Self(values.to_vec())
    }

    /// The value given for `p`.
    pub fn get(&self, p: Param) -> Option<f64> {
        self.0.iter().find(|(q, _)| *q == p).map(|(_, x)| *x)
    }

    /// The flags given, in the table's order.
    pub fn given(&self) -> impl Iterator<Item = (Param, f64)> + '_ {
        self.0.iter().copied()
    }

    pub fn any(&self) -> bool {
        !self.0.is_empty()
    }
}

/// The flag's name without its dashes: `alpha`, `drive-time`. Made
/// once per command line built (clap keeps `'static` names).
fn long_name(p: Param) -> &'static str {
    match p.name() {
        name if !name.contains('_') => name,
        name => Box::leak(name.replace('_', "-").into_boxed_str()),
    }
}

/// A model parameter's flag: `--alpha DEG`, typed as the table says.
fn value_flag(p: Param) -> Arg {
    let s = p.spec();
    let arg = Arg::new(s.name)
        .long(long_name(p))
        .value_name(s.value_name)
        .help(p.help(true))
        .allow_negative_numbers(true);
    match s.kind {
        Kind::Int => arg.value_parser(clap::value_parser!(usize)),
        Kind::Float => arg.value_parser(clap::value_parser!(f64)),
    }
}

/// The value of flag `p` in `m`, as a number.
fn value_of(m: &ArgMatches, p: Param) -> Option<f64> {
    match p.spec().kind {
        Kind::Int => m.get_one::<usize>(p.name()).map(|&n| n as f64),
        Kind::Float => m.get_one::<f64>(p.name()).copied(),
    }
}

impl FromArgMatches for ParamFlags {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut flags = Self::default();
        flags.update_from_arg_matches(m)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        for p in Param::MODEL {
            if let Some(x) = value_of(m, p) {
                self.0.retain(|(q, _)| *q != p);
                self.0.push((p, x));
            }
        }
        self.0.sort_by_key(|(p, _)| *p);
        Ok(())
    }
}

impl Args for ParamFlags {
    fn augment_args(cmd: Command) -> Command {
        Param::MODEL
            .into_iter()
            .fold(cmd, |cmd, p| cmd.arg(value_flag(p)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// The grid flags as given: each parameter's axis, its text (a range
/// START:STOP:STEP or a comma list), in the table's order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GridFlags(Vec<(Param, String)>);

impl GridFlags {
    /// The axes given, in the table's order ([`Param::ALL`]).
    pub fn given(&self) -> Vec<(Param, &str)> {
        self.0.iter().map(|(p, v)| (*p, v.as_str())).collect()
    }
}

/// A parameter's axis flag: `--alpha RANGE`, its help the table's
/// (`--alpha` of the model and of a grid are never on one command).
fn axis_flag(p: Param) -> Arg {
    let s = p.spec();
    Arg::new(s.name)
        .long(long_name(p))
        .value_name("RANGE")
        .allow_hyphen_values(true)
        .help(format!("{} (left out: not varied)", s.doc))
}

impl FromArgMatches for GridFlags {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut flags = Self::default();
        flags.update_from_arg_matches(m)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        for p in Param::ALL {
            if let Some(v) = m.get_one::<String>(p.name()) {
                self.0.retain(|(q, _)| *q != p);
                self.0.push((p, v.clone()));
            }
        }
        self.0.sort_by_key(|(p, _)| *p);
        Ok(())
    }
}

impl Args for GridFlags {
    fn augment_args(cmd: Command) -> Command {
        Param::ALL
            .into_iter()
            .fold(cmd, |cmd, p| cmd.arg(axis_flag(p)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}
