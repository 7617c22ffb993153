// The shapes of the lab's web API (docs/web-api.md): what the server sends is web/src/api_types.ts,
// written from the lab's declaration; here only what the page sends.
export * from "./api_types";

export type ControlAction = "play" | "pause" | "step" | "reset";
