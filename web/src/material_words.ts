// The plate's materials of the paper's Table I (assets/paper/table1.yaml) by their names in the
// page's language: each by its message material-KEY, else by the lab's (English) name.
import { hasMessage, t } from "./i18n";

/** "Bois poli" for polished-wood on a French page; the lab's name where no catalogue has one. */
export function materialWords(key: string, name: string): string {
  const id = `material-${key}`;
  return hasMessage(id) ? t(id) : name;
}
