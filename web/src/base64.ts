// A file's bytes in base64, as btoa() writes them: how the page sends a file inside a JSON
// request (the lab report's measurement).

/** The bytes of `blob` in base64. */
export async function base64Of(blob: Blob): Promise<string> {
  const bytes = new Uint8Array(await blob.arrayBuffer());
  // btoa takes a "binary string", one character a byte, built a chunk at a time (a spread of
  // millions of arguments overflows the stack).
  const CHUNK = 0x8000;
  let binary = "";
  for (let at = 0; at < bytes.length; at += CHUNK) {
    binary += String.fromCharCode(...bytes.subarray(at, at + CHUNK));
  }
  return btoa(binary);
}
