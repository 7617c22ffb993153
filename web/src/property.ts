// A value views observe, in the spirit of PhET's axon Property: the controller sets it, and every
// listener hears each change. Views read the model's properties; none reads another view.

export type Listener<T> = (value: T, previous: T) => void;

export class Property<T> {
  private readonly listeners: Listener<T>[] = [];

  constructor(private current: T) {}

  get value(): T {
    return this.current;
  }

  /** Sets the value; the listeners hear it when it changed. */
  set value(next: T) {
    if (Object.is(next, this.current)) return;
    const previous = this.current;
    this.current = next;
    for (const listener of this.listeners) listener(next, previous);
  }

  /** Calls `listener` now with the value, and on each change. */
  link(listener: Listener<T>): void {
    this.listeners.push(listener);
    listener(this.current, this.current);
  }

  /** Calls `listener` on each change from now on. */
  lazyLink(listener: Listener<T>): void {
    this.listeners.push(listener);
  }
}
