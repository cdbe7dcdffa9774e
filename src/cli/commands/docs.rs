//! `ladder completions` and `ladder man`: the shell completion scripts and
//! the manual page, from the command's own definition.

use crate::cli::*;
use crate::error::{Error, Result};

/// The completion script of `shell` for every command and flag.
pub(crate) fn completions(shell: clap_complete::Shell) -> Result<String> {
    use clap::CommandFactory;
    let mut bytes = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "ladder", &mut bytes);
    String::from_utf8(bytes).map_err(|_| Error::failed("the completion script is not UTF-8"))
}

/// The manual page, ladder(1), in roff: the commands' help, one section
/// each.
pub(crate) fn man_page() -> Result<String> {
    use clap::CommandFactory;
    let cmd = Cli::command();
    let mut bytes = Vec::new();
    let failed = |e: std::io::Error| Error::failed(format!("cannot write the man page: {e}"));
    let man = clap_mangen::Man::new(cmd.clone());
    man.render_title(&mut bytes).map_err(failed)?;
    man.render_name_section(&mut bytes).map_err(failed)?;
    man.render_synopsis_section(&mut bytes).map_err(failed)?;
    man.render_description_section(&mut bytes).map_err(failed)?;
    man.render_subcommands_section(&mut bytes).map_err(failed)?;
    for sub in cmd.get_subcommands().filter(|c| !c.is_hide_set()) {
        let name = sub.get_name().to_string();
        let sub = sub.clone().bin_name(format!("ladder {name}"));
        let man = clap_mangen::Man::new(sub);
        bytes.extend_from_slice(format!(".SH \"LADDER {}\"\n", name.to_uppercase()).as_bytes());
        man.render_synopsis_section(&mut bytes).map_err(failed)?;
        man.render_description_section(&mut bytes).map_err(failed)?;
        man.render_options_section(&mut bytes).map_err(failed)?;
    }
    man.render_version_section(&mut bytes).map_err(failed)?;
    String::from_utf8(bytes).map_err(|_| Error::failed("the man page is not UTF-8"))
}
