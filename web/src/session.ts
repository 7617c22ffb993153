// The page's one session at a time: starting one ends the one before (once the new one is
// made, so a refused set-up leaves the running one alone), its stream, its playback commands.
// The session's key stays here, in memory: every control sends it, and nothing else sees it.
import {
  control,
  createSession,
  endSession,
  stream,
  type StreamHandle,
  type StreamHandlers,
} from "./lab_client";
import { t } from "./i18n";
import type { ControlAction, ControlReply, PlaybackSpeed, Session } from "./lab_types";

/** A newer set-up was asked for while this one was being made. */
export class Superseded extends Error {
  constructor() {
    super(t("lab-superseded"));
    this.name = "Superseded";
  }
}

export class SessionKeeper {
  private session: Session | null = null;
  private listening: StreamHandle | null = null;
  private asked = 0;

  constructor(private readonly handlers: StreamHandlers) {
    window.addEventListener("pagehide", () => this.end());
  }

  get current(): Session | null {
    return this.session;
  }

  /** Makes the set-up's session (throws SetupError when refused) and listens to it; `name`
   * is who runs it, for the class's table. */
  async open(scene: string, set: string[], name?: string): Promise<Session> {
    const ticket = ++this.asked;
    const made = await createSession(scene, set, name);
    if (ticket !== this.asked) {
      void endSession(made);
      throw new Superseded();
    }
    this.end();
    this.session = made;
    this.listen();
    return made;
  }

  /** Plays, pauses, steps, resets, sets the slow motion or names the student. */
  async command(
    command: ControlAction | { speed: PlaybackSpeed } | { name: string },
  ): Promise<ControlReply | null> {
    const session = this.session;
    if (!session) return null;
    return control(session, command);
  }

  /** Stops listening and ends the session (the stream goes on after `done` until then). */
  end(): void {
    this.listening?.close();
    this.listening = null;
    if (this.session) void endSession(this.session);
    this.session = null;
  }

  /** The server stopped (its stream said `closed`): forget the session, ask it nothing more. */
  drop(): void {
    this.asked += 1;
    this.listening?.close();
    this.listening = null;
    this.session = null;
  }

  private listen(): void {
    if (this.listening || !this.session) return;
    this.listening = stream(this.session, this.handlers);
  }
}
