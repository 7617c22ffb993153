// Live plots (uPlot) over a sliding window: the plate's x(t) with the thick-plate theory the
// lab sends beside it (x_theory: about a tilted rig's centre, from where the run started), and
// the Hall sensor's ADC counts with the estimator's pulse times marked (dashed lines). Colours:
// palette.ts.
import uPlot from "uplot";
import { t } from "./i18n";
import type { LabState, Rig } from "./lab_types";
import { tickLabels } from "./page_numbers";
import { PLOT_COLORS as COLORS } from "./palette";
import { SlidingWindow } from "./sliding_window";

const WINDOW_S = 5;
/** The plots redraw at most this often (software rendering draws the 3D view too). */
const REDRAW_MS = 100;
const LEGEND_PX = 28;

function chartSize(box: HTMLElement): { width: number; height: number } {
  return {
    width: Math.max(160, box.clientWidth),
    height: Math.max(120, box.clientHeight - LEGEND_PX),
  };
}

function windowRange(last: number | null): [number, number] {
  const end = Math.max(WINDOW_S, last ?? 0);
  return [end - WINDOW_S, end];
}

/** An axis: its label, its ticks written in the page's language. */
export function axis(label: string): uPlot.Axis {
  return {
    label,
    labelSize: 18,
    size: 44,
    stroke: "#333",
    grid: { stroke: "#e3e3e3", width: 1 },
    values: tickLabels(),
  };
}

/** A chart that follows its box's size and redraws at most every REDRAW_MS. */
export class LiveChart {
  readonly chart: uPlot;
  private scheduled = 0;
  private lastDraw = 0;
  private readonly resize: ResizeObserver;

  constructor(
    box: HTMLElement,
    options: Omit<uPlot.Options, "width" | "height">,
    private readonly data: SlidingWindow,
  ) {
    this.chart = new uPlot(
      { ...options, ...chartSize(box) },
      data.view() as uPlot.AlignedData,
      box,
    );
    this.resize = new ResizeObserver(() => this.chart.setSize(chartSize(box)));
    this.resize.observe(box);
  }

  scheduleRedraw(): void {
    if (this.scheduled) return;
    const wait = Math.max(0, this.lastDraw + REDRAW_MS - performance.now());
    this.scheduled = window.setTimeout(() => {
      requestAnimationFrame(() => {
        this.scheduled = 0;
        this.lastDraw = performance.now();
        this.chart.setData(this.data.view() as uPlot.AlignedData);
      });
    }, wait);
  }

  destroy(): void {
    window.clearTimeout(this.scheduled);
    this.resize.disconnect();
    this.chart.destroy();
  }
}

/** x(t) in mm, with the lab's theory curve where the rig has one. */
export class PositionPlot {
  private readonly data = new SlidingWindow(3, WINDOW_S);
  private readonly live: LiveChart;

  constructor(box: HTMLElement) {
    this.live = new LiveChart(
      box,
      {
        scales: {
          x: { time: false, range: () => windowRange(this.data.lastTime) },
          y: {
            range: (_u, min, max) => {
              const reach = Math.max(Math.abs(min || 0), Math.abs(max || 0), 1);
              return [-1.1 * reach, 1.1 * reach];
            },
          },
        },
        series: [
          { label: "t (s)" },
          { label: t("plot-position-series"), stroke: COLORS.x, width: 2, points: { show: false } },
          {
            label: t("plot-theory-series"),
            stroke: COLORS.theory,
            width: 1.5,
            dash: [6, 4],
            points: { show: false },
          },
        ],
        axes: [axis("t (s)"), axis(t("plot-position-series"))],
        legend: { live: false },
        cursor: { drag: { x: false, y: false } },
      },
      this.data,
    );
  }

  setRig(rig: Rig): void {
    this.live.chart.setSeries(2, { show: rig.omega !== null });
    this.clear();
  }

  clear(): void {
    this.data.clear();
    this.live.scheduleRedraw();
  }

  /** The samples plotted: times [s] and x [mm]. */
  samples(): [number[], number[]] {
    const [t = [], x = []] = this.data.view();
    return [t, x];
  }

  push(state: LabState): void {
    const last = this.data.lastTime;
    if (last !== null && state.t < last) this.data.clear();
    if (last !== null && state.t === last) return;
    const theory = state.x_theory === null ? NaN : state.x_theory * 1000;
    this.data.push([state.t, state.x * 1000, theory]);
    this.live.scheduleRedraw();
  }
}

/** The Hall sensor's ADC counts, the estimator's pulse times drawn as red lines. */
export class HallPlot {
  private readonly data = new SlidingWindow(2, WINDOW_S);
  private readonly live: LiveChart;
  private pulses: number[] = [];

  constructor(box: HTMLElement) {
    this.live = new LiveChart(
      box,
      {
        scales: { x: { time: false, range: () => windowRange(this.data.lastTime) } },
        series: [
          { label: "t (s)" },
          {
            label: t("plot-hall-column"),
            stroke: COLORS.hall,
            width: 1,
            points: { show: false },
          },
        ],
        axes: [axis("t (s)"), axis(t("plot-adc-axis"))],
        legend: { live: false },
        cursor: { drag: { x: false, y: false } },
        hooks: { draw: [(u) => this.drawPulses(u)] },
      },
      this.data,
    );
  }

  clear(): void {
    this.data.clear();
    this.pulses = [];
    this.live.scheduleRedraw();
  }

  /** The samples plotted: times [s] and ADC counts. */
  samples(): [number[], number[]] {
    const [t = [], adc = []] = this.data.view();
    return [t, adc];
  }

  push(state: LabState): void {
    const last = this.data.lastTime;
    if (last !== null && state.hall.length > 0 && state.hall[0]![0] < last) this.clear();
    for (const [t, adc] of state.hall) this.data.push([t, adc]);
    if (state.pulses.length > 0) {
      this.pulses.push(...state.pulses);
      const [from] = windowRange(this.data.lastTime);
      this.pulses = this.pulses.filter((t) => t >= from - 1);
    }
    if (state.hall.length > 0 || state.pulses.length > 0) this.live.scheduleRedraw();
  }

  private drawPulses(u: uPlot): void {
    const ctx = u.ctx;
    const { left, top, width, height } = u.bbox;
    ctx.save();
    ctx.strokeStyle = COLORS.pulse;
    ctx.lineWidth = Math.max(1, devicePixelRatio);
    ctx.setLineDash([4 * devicePixelRatio, 3 * devicePixelRatio]);
    ctx.beginPath();
    for (const t of this.pulses) {
      const x = u.valToPos(t, "x", true);
      if (x < left || x > left + width) continue;
      ctx.moveTo(x, top);
      ctx.lineTo(x, top + height);
    }
    ctx.stroke();
    ctx.restore();
  }
}
