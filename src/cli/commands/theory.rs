//! `ladder theory`: the linear theory's numbers for one ladder.

use crate::cli::*;
use crate::error::Result;
use crate::output;
use crate::scene;

pub(crate) fn theory(args: &TheoryArgs) -> Result<()> {
    let params = scene::Model {
        alpha: args.alpha,
        n: args.n,
        b: args.b,
        ..scene::Model::default()
    }
    .params()?;
    let report = crate::theory::TheoryReport::compute(&params)?;
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&report.to_table())
    }
}
