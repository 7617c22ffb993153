// The two lab clients offer the same calls with the same types: the page is built with either
// (web/build.mjs), and tsc fails here when one gains, loses or changes a call the other has.
import type * as server from "./lab_client";
import type * as browser from "./lab_client_worker";

type Calls<T> = Omit<T, "LAB_PLACE">;
export type ServerOffersTheBrowsers =
  Calls<typeof server> extends Calls<typeof browser> ? true : never;
export type BrowserOffersTheServers =
  Calls<typeof browser> extends Calls<typeof server> ? true : never;
export const sameCalls: [ServerOffersTheBrowsers, BrowserOffersTheServers] = [true, true];
