// The scenes a lab offers, by what they are in the page's language: the shipped scenes each by
// its message, any other by the first words of its file's first comment (the lab's `title`, up to
// its first ":" or "("), its name beside it for a link's `scene=`.
import { hasMessage, t } from "./i18n";

export const SCENE_MESSAGES: Readonly<Record<string, string>> = {
  "paper-rig": "scene-paper-rig",
  "paper-rig-77K": "scene-paper-rig-77K",
  "paper-rig-77K-warming": "scene-paper-rig-77K-warming",
  minimal: "scene-minimal",
  "roller-ramp": "scene-roller-ramp",
};

/** "The paper's rig (paper-rig)": what the scene is, and its name. */
export function sceneWords(name: string, title: string): string {
  const id = SCENE_MESSAGES[name];
  const what = id !== undefined && hasMessage(id) ? t(id) : (title.split(/[:(]/)[0] ?? "").trim();
  return what ? `${what} (${name})` : name;
}
