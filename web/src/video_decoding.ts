// A phone's video decoded in the lab's worker with the browser's own decoder (WebCodecs), for the
// static site, whose WebAssembly lab has no libav: the MP4 or MOV container read by mp4box.js,
// each frame of its first video track decoded, made grey (Rec. 601 luma) and averaged down to the
// width the lab's tracker reads, as the native lab's decoder module does with libav (an area
// average). The lab then follows the plate in these frames with its own tracker
// (src/tracking/given_video.hpp).
import { createFile, DataStream, MP4BoxBuffer, type Sample, type Track } from "mp4box";

export interface GreyFrame {
  tS: number;
  width: number;
  height: number;
  levels: Uint8Array;
}

export interface DecodedVideo {
  container: string;
  codec: string;
  width: number;
  height: number;
  fps: number;
  scale: number;
  frames: GreyFrame[];
}

/** Why a file that is a video cannot be decoded here; thrown with the words the page shows. */
export class VideoNotDecoded extends Error {}

/** The container a video file is in, by its first bytes; null for a file that is no video. */
export function videoContainer(bytes: Uint8Array): string | null {
  const text = (from: number, to: number) => String.fromCharCode(...bytes.subarray(from, to));
  if (bytes.length >= 12 && text(4, 8) === "ftyp") return text(8, 10) === "qt" ? "mov" : "mp4";
  if (bytes[0] === 0x1a && bytes[1] === 0x45 && bytes[2] === 0xdf && bytes[3] === 0xa3)
    return "webm";
  if (bytes.length >= 12 && text(0, 4) === "RIFF" && text(8, 12) === "AVI ") return "avi";
  return null;
}

const ELSEWHERE =
  "read it with frictionlab estimate on a computer, or follow the plate with Tracker and choose " +
  "Tracker's data file here";

/** The decoder's description of an H.264, HEVC, VP9 or AV1 track (its configuration box). */
function description(file: ReturnType<typeof createFile>, track: Track): Uint8Array | undefined {
  const trak = file.getTrackById(track.id);
  for (const entry of trak.mdia.minf.stbl.stsd.entries) {
    const box = (entry as unknown as Record<string, { write?: (s: DataStream) => void }>)[
      ["avcC", "hvcC", "vpcC", "av1C"].find((name) => name in entry) ?? ""
    ];
    if (box?.write) {
      const stream = new DataStream(undefined, 0); // big-endian, as MP4 is
      box.write(stream);
      return new Uint8Array(stream.buffer, 8); // the box without its header
    }
  }
  return undefined;
}

/** The frame's grey levels at `width` x `height`, each pixel the mean of the source pixels it
 * covers (fractions at its edges), from the source's RGBA. */
function areaGrey(rgba: Uint8ClampedArray, w: number, h: number, width: number, height: number) {
  const luma = new Float32Array(w * h);
  for (let i = 0; i < w * h; i += 1)
    luma[i] = 0.299 * rgba[4 * i]! + 0.587 * rgba[4 * i + 1]! + 0.114 * rgba[4 * i + 2]!;
  // One axis at a time: the weights of the source columns (then rows) each target one covers.
  const weights = (from: number, to: number) => {
    const out: { first: number; w: number[] }[] = [];
    const step = from / to;
    for (let k = 0; k < to; k += 1) {
      const a = k * step;
      const b = (k + 1) * step;
      const first = Math.floor(a);
      const w: number[] = [];
      for (let s = first; s < Math.min(Math.ceil(b), from); s += 1)
        w.push((Math.min(b, s + 1) - Math.max(a, s)) / step);
      out.push({ first, w });
    }
    return out;
  };
  const across = weights(w, width);
  const down = weights(h, height);
  const rows = new Float32Array(width * h);
  for (let y = 0; y < h; y += 1)
    for (let x = 0; x < width; x += 1) {
      const { first, w: ws } = across[x]!;
      let sum = 0;
      for (let j = 0; j < ws.length; j += 1) sum += ws[j]! * luma[y * w + first + j]!;
      rows[y * width + x] = sum;
    }
  const levels = new Uint8Array(width * height);
  for (let y = 0; y < height; y += 1) {
    const { first, w: ws } = down[y]!;
    for (let x = 0; x < width; x += 1) {
      let sum = 0;
      for (let j = 0; j < ws.length; j += 1) sum += ws[j]! * rows[(first + j) * width + x]!;
      levels[y * width + x] = Math.min(255, Math.max(0, Math.round(sum)));
    }
  }
  return levels;
}

/** Decodes the video in `bytes` into grey frames at most `mostWidth` across; throws
 * VideoNotDecoded saying why a video cannot be. */
export async function decodeVideo(bytes: ArrayBuffer, mostWidth: number): Promise<DecodedVideo> {
  const container = videoContainer(new Uint8Array(bytes));
  if (container === null || container === "webm" || container === "avi")
    throw new VideoNotDecoded(
      `the lab in this browser reads MP4 and MOV videos, not ${container?.toUpperCase() ?? "this file"}: ${ELSEWHERE}`,
    );
  if (typeof VideoDecoder === "undefined" || typeof OffscreenCanvas === "undefined")
    throw new VideoNotDecoded(
      `this browser has no video decoder for pages (WebCodecs): open the page in a recent Chrome, Edge or Safari, or ${ELSEWHERE}`,
    );
  const file = createFile();
  const movie = await new Promise<{ track: Track; samples: Sample[] }>((done, fail) => {
    let track: Track | null = null;
    const samples: Sample[] = [];
    file.onError = (_module, message) =>
      fail(new VideoNotDecoded(`the video cannot be read (${message}): the file is damaged`));
    file.onReady = (info) => {
      track = info.videoTracks[0] ?? null;
      if (!track) {
        fail(new VideoNotDecoded("the file holds no video track"));
        return;
      }
      file.setExtractionOptions(track.id, null, { nbSamples: Infinity });
      file.start();
    };
    file.onSamples = (_id, _user, got) => samples.push(...got);
    file.appendBuffer(MP4BoxBuffer.fromArrayBuffer(bytes, 0));
    file.flush();
    if (track) done({ track, samples });
    else
      fail(
        new VideoNotDecoded(
          "the container has no movie box (moov): the file is cut short or damaged",
        ),
      );
  });
  const { track, samples } = movie;
  const width = track.video?.width ?? track.track_width;
  const height = track.video?.height ?? track.track_height;
  const outWidth = Math.min(width, mostWidth);
  const outHeight = Math.max(1, Math.round((height * outWidth) / width));
  const config: VideoDecoderConfig = { codec: track.codec, codedWidth: width, codedHeight: height };
  const box = description(file, track);
  if (box) config.description = box;
  const support = await VideoDecoder.isConfigSupported(config).catch(() => ({ supported: false }));
  if (!support.supported)
    throw new VideoNotDecoded(
      `this browser cannot decode the video's ${track.codec} (HEVC, an iPhone's "High Efficiency", is the usual one): record in H.264 ("Most Compatible"), or ${ELSEWHERE}`,
    );

  const canvas = new OffscreenCanvas(width, height);
  const context = canvas.getContext("2d", { willReadFrequently: true });
  if (!context)
    throw new VideoNotDecoded(`this browser cannot draw a video's frames: ${ELSEWHERE}`);
  const frames: GreyFrame[] = [];
  let failure: Error | null = null;
  const decoder = new VideoDecoder({
    output: (frame) => {
      context.drawImage(frame, 0, 0, width, height);
      const rgba = context.getImageData(0, 0, width, height).data;
      frames.push({
        tS: frame.timestamp / 1e6,
        width: outWidth,
        height: outHeight,
        levels: areaGrey(rgba, width, height, outWidth, outHeight),
      });
      frame.close();
    },
    error: (error) => (failure = error),
  });
  decoder.configure(config);
  for (const sample of samples) {
    if (!sample.data) continue;
    decoder.decode(
      new EncodedVideoChunk({
        type: sample.is_sync ? "key" : "delta",
        timestamp: (1e6 * sample.cts) / sample.timescale,
        duration: (1e6 * sample.duration) / sample.timescale,
        data: sample.data,
      }),
    );
  }
  await decoder.flush().catch((error: unknown) => (failure ??= error as Error));
  decoder.close();
  if (failure)
    throw new VideoNotDecoded(`the browser's decoder stopped: ${(failure as Error).message}`);
  frames.sort((a, b) => a.tS - b.tS);
  const seconds = track.duration / track.timescale;
  return {
    container,
    codec: track.codec,
    width,
    height,
    fps: seconds > 0 ? samples.length / seconds : 0,
    scale: outWidth / width,
    frames,
  };
}
