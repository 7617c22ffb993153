// The live rig's Hall signal (uPlot): its ADC counts over the last 10 s, with the end of each
// period the rig's estimator judged drawn as a line: orange-red where it accepted it, grey dashed
// where it rejected it (palette.ts).
import uPlot from "uplot";
import { t } from "./i18n";
import type { PeriodRow } from "./lab_types";
import { PLOT_COLORS as COLORS } from "./palette";
import { axis, LiveChart } from "./plots";
import { SlidingWindow } from "./sliding_window";

const WINDOW_S = 10;

interface PeriodEnd {
  t: number;
  accepted: boolean;
}

export class RigPlot {
  private readonly data = new SlidingWindow(2, WINDOW_S);
  private readonly live: LiveChart;
  private ends: PeriodEnd[] = [];

  constructor(box: HTMLElement) {
    this.live = new LiveChart(
      box,
      {
        scales: { x: { time: false, range: () => this.range() } },
        series: [
          { label: "t (s)" },
          {
            label: t("plot-rig-hall-series"),
            stroke: COLORS.hall,
            width: 1,
            points: { show: false },
          },
        ],
        axes: [axis("t (s)"), axis(t("plot-adc-axis"))],
        legend: { live: false },
        cursor: { drag: { x: false, y: false } },
        hooks: { draw: [(u) => this.drawEnds(u)] },
      },
      this.data,
    );
  }

  clear(): void {
    this.data.clear();
    this.ends = [];
    this.live.scheduleRedraw();
  }

  push(hall: [number, number][], periods: PeriodRow[]): void {
    const last = this.data.lastTime;
    if (last !== null && hall.length > 0 && hall[0]![0] < last) this.clear();
    for (const [t, adc] of hall) this.data.push([t, adc]);
    for (const [, end, , accepted] of periods) this.ends.push({ t: end, accepted });
    if (periods.length > 0) {
      const [from] = this.range();
      this.ends = this.ends.filter((end) => end.t >= from - 1);
    }
    if (hall.length > 0 || periods.length > 0) this.live.scheduleRedraw();
  }

  private range(): [number, number] {
    const end = Math.max(WINDOW_S, this.data.lastTime ?? 0);
    return [end - WINDOW_S, end];
  }

  private drawEnds(u: uPlot): void {
    const ctx = u.ctx;
    const { left, top, width, height } = u.bbox;
    ctx.save();
    ctx.lineWidth = Math.max(1, devicePixelRatio);
    for (const accepted of [false, true]) {
      ctx.strokeStyle = accepted ? COLORS.accepted : COLORS.rejected;
      ctx.setLineDash(accepted ? [] : [4 * devicePixelRatio, 3 * devicePixelRatio]);
      ctx.beginPath();
      for (const end of this.ends) {
        if (end.accepted !== accepted) continue;
        const x = u.valToPos(end.t, "x", true);
        if (x < left || x > left + width) continue;
        ctx.moveTo(x, top);
        ctx.lineTo(x, top + height);
      }
      ctx.stroke();
    }
    ctx.restore();
  }
}
