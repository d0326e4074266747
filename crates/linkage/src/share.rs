//! A whole scene in a link: the scene file's text compressed (raw DEFLATE) and
//! base64url-encoded, so that a custom mechanism travels in a URL fragment
//! (`#doc=1.…`) and comes back byte for byte. The leading `1.` is the format's
//! version. Both directions have limits, so that a link stays shareable and a damaged
//! or hostile one cannot exhaust memory; each failure says what is wrong.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use thiserror::Error;

/// Longest payload written or read, characters: links longer than this are cut by
/// chat and mail programs and refused by some servers.
pub const MAX_PAYLOAD_CHARS: usize = 32 * 1024;
/// Largest scene text a payload may unpack to, bytes (a scene file is a few kB).
pub const MAX_SCENE_BYTES: usize = 1024 * 1024;
/// The version prefix of the payload.
const VERSION: &str = "1.";
/// The fragment key that carries a scene.
pub const FRAGMENT_KEY: &str = "doc";

/// Why a scene could not be packed into, or unpacked from, a link.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum ShareError {
    /// The packed scene is longer than a link may be.
    #[error(
        "the scene packs to {chars} characters, more than the {max} a link may carry: save it as a file instead"
    )]
    TooLong {
        /// Its length packed.
        chars: usize,
        /// The limit.
        max: usize,
    },
    /// No payload was found.
    #[error("the link carries no scene (expected doc=1.… in the fragment)")]
    Missing,
    /// The payload is not of a version this program reads.
    #[error("the scene in the link is in an unknown format (it starts {start:?}, expected \"1.\")")]
    UnknownVersion {
        /// Its first characters.
        start: String,
    },
    /// The payload has characters outside base64url, or is cut.
    #[error("the link is damaged: {0}")]
    NotBase64(String),
    /// The compressed data does not unpack.
    #[error("the link is damaged: its data does not unpack ({0})")]
    NotDeflate(String),
    /// It unpacks to more than a scene can be.
    #[error("the scene in the link unpacks to more than {max} bytes")]
    Unpacks {
        /// The limit.
        max: usize,
    },
    /// It unpacks to bytes that are not text.
    #[error("the scene in the link is not UTF-8 text")]
    NotText,
}

/// The payload for `scene_text`: `1.` then the compressed text in base64url.
pub fn encode(scene_text: &str) -> Result<String, ShareError> {
    let packed = miniz_oxide::deflate::compress_to_vec(scene_text.as_bytes(), 9);
    let payload = format!("{VERSION}{}", URL_SAFE_NO_PAD.encode(packed));
    if payload.len() > MAX_PAYLOAD_CHARS {
        return Err(ShareError::TooLong {
            chars: payload.len(),
            max: MAX_PAYLOAD_CHARS,
        });
    }
    Ok(payload)
}

/// The scene text a payload carries. Accepts the payload alone, `doc=…`, a fragment
/// (`#scene=…&doc=…`) or a whole URL.
pub fn decode(link: &str) -> Result<String, ShareError> {
    let payload = payload_of(link.trim()).ok_or(ShareError::Missing)?;
    if payload.len() > MAX_PAYLOAD_CHARS {
        return Err(ShareError::TooLong {
            chars: payload.len(),
            max: MAX_PAYLOAD_CHARS,
        });
    }
    let body = payload
        .strip_prefix(VERSION)
        .ok_or_else(|| ShareError::UnknownVersion {
            start: payload.chars().take(8).collect(),
        })?;
    let packed = URL_SAFE_NO_PAD
        .decode(body)
        .map_err(|e| ShareError::NotBase64(e.to_string()))?;
    let text = miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, MAX_SCENE_BYTES)
        .map_err(|e| match e.status {
            miniz_oxide::inflate::TINFLStatus::HasMoreOutput => ShareError::Unpacks {
                max: MAX_SCENE_BYTES,
            },
            status => ShareError::NotDeflate(format!("{status:?}")),
        })?;
    String::from_utf8(text).map_err(|_| ShareError::NotText)
}

/// The payload inside a link: after `#` if there is one, the value of `doc=` among
/// `&`-separated keys if there is one, else the whole text.
fn payload_of(link: &str) -> Option<&str> {
    let fragment = link.split_once('#').map_or(link, |(_, f)| f);
    let key = format!("{FRAGMENT_KEY}=");
    let found = fragment
        .split('&')
        .find_map(|part| part.strip_prefix(key.as_str()));
    let payload = found.unwrap_or(fragment);
    (!payload.is_empty()).then_some(payload)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_payload_is_found_in_a_url_a_fragment_or_alone() {
        for link in [
            "1.abc",
            "doc=1.abc",
            "#doc=1.abc",
            "#scene=x&doc=1.abc&input=3",
            "https://h/p/#input=3&doc=1.abc",
        ] {
            assert_eq!(payload_of(link), Some("1.abc"), "{link}");
        }
        assert_eq!(payload_of("#"), None);
        assert_eq!(payload_of(""), None);
    }

    #[test]
    fn text_round_trips_byte_for_byte() {
        for text in ["", "(name: \"é — ω\")\n", &"(x: 1.0),\n".repeat(500)] {
            assert_eq!(decode(&encode(text).expect("fits")).expect("unpacks"), text);
        }
    }

    #[test]
    fn a_scene_too_large_for_a_link_is_refused_with_the_limit() {
        // Text that hardly compresses: letters from a xorshift generator.
        let mut x = 0x9E37_79B9_7F4A_7C15_u64;
        let text: String = (0..100_000)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                char::from(b'a' + (x % 26) as u8)
            })
            .collect();
        let e = encode(&text).expect_err("too long");
        assert!(
            matches!(
                e,
                ShareError::TooLong {
                    max: MAX_PAYLOAD_CHARS,
                    ..
                }
            ),
            "{e}"
        );
    }
}
