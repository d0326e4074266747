//! `linkage share`: a scene as a share link's fragment, and a link back to the
//! scene's text.

use linkage::Mechanism;

use crate::error::{CliError, Result};

/// `share SCENE`: the fragment for the scene (checked to load first); `share --decode
/// LINK`: the scene text it carries, exactly.
pub(crate) fn share(scene: Option<&std::path::Path>, decode: Option<&str>) -> Result<String> {
    if let Some(link) = decode {
        return Ok(linkage::share::decode(link)?);
    }
    let path = scene.ok_or_else(|| CliError::refused("give a scene file, or --decode LINK"))?;
    let text = std::fs::read_to_string(path).map_err(|source| CliError::ReadScene {
        path: path.to_path_buf(),
        source,
    })?;
    Mechanism::from_ron(&text).map_err(|e| CliError::in_file(path, e))?;
    let payload = linkage::share::encode(&text)?;
    Ok(format!("{}={payload}\n", linkage::share::FRAGMENT_KEY))
}
