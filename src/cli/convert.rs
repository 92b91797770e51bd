//! `lispcad convert IN.dxf... -o OUT`: open drawings and write them in another format (or
//! back as DXF, losslessly, in the version they were read in). No script runs.

use std::path::{Path, PathBuf};

use clap::Args;

use super::{Common, EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::output::{DxfProfile, Format, OutputOptions};

#[derive(Args, Debug)]
pub struct ConvertArgs {
    /// The drawings to read (DXF, ASCII or binary).
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Where to write (.svg or .dxf); with several inputs a pattern with `{stem}` (the input's
    /// file name without extension), e.g. `out/{stem}.svg`. Repeatable.
    #[arg(short = 'o', long = "output", value_name = "OUT", required = true)]
    pub outputs: Vec<PathBuf>,
}

fn options(common: &Common) -> Result<OutputOptions, String> {
    let mut o = OutputOptions::default();
    if let Some(p) = &common.dxf_profile {
        o.dxf_profile = p.parse::<DxfProfile>().map_err(|e| e.to_string())?;
    }
    if let Some(t) = common.cam_tol {
        o.cam_tol = t;
    }
    o.validate().map_err(|e| e.to_string())?;
    Ok(o)
}

/// The output path of `input` for a pattern.
fn output_for(pattern: &Path, input: &Path) -> PathBuf {
    let stem = input
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    PathBuf::from(pattern.to_string_lossy().replace("{stem}", &stem))
}

pub fn convert(args: &ConvertArgs, common: &Common) -> i32 {
    let opts = match options(common) {
        Ok(o) => o,
        Err(m) => {
            eprintln!("error: {m}");
            return EXIT_USAGE;
        }
    };
    let many = args.inputs.len() > 1;
    let mut plan: Vec<(PathBuf, Vec<PathBuf>)> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for input in &args.inputs {
        let mut outs = Vec::new();
        for pat in &args.outputs {
            if let Err(e) = Format::from_path(pat) {
                eprintln!("error: {e}");
                return EXIT_USAGE;
            }
            if many && !pat.to_string_lossy().contains("{stem}") {
                eprintln!(
                    "error: several inputs need an output pattern with {{stem}}, got {}",
                    pat.display()
                );
                return EXIT_USAGE;
            }
            let out = output_for(pat, input);
            if !seen.insert(out.clone()) {
                eprintln!(
                    "error: two inputs would both write {} (same file stem)",
                    out.display()
                );
                return EXIT_USAGE;
            }
            outs.push(out);
        }
        plan.push((input.clone(), outs));
    }
    let mut status = EXIT_OK;
    for (input, outs) in plan {
        let d = match crate::output::open_drawing(&input, common.recover) {
            Ok(d) => d,
            Err(e) => {
                eprintln!("error: {e}");
                status = EXIT_SCRIPT_ERROR;
                continue;
            }
        };
        if let Some(n) = crate::output::dxfin::recover_note(&input, &d) {
            eprintln!("{n}");
        }
        for out in outs {
            if let Err(e) = crate::output::save(&d, &out, &opts) {
                eprintln!("error: {e}");
                status = EXIT_SCRIPT_ERROR;
            }
        }
    }
    status
}
