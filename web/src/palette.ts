// The page's colours for what they tell apart: Okabe and Ito's palette, which readers with
// protanopia or deuteranopia tell apart too, each at least 3:1 against the white or light grey
// behind it. app.css's legend (.key.normal, .key.friction, .key.weight) repeats the forces'.
//   Okabe M., Ito K. (2008), "Color Universal Design (CUD): how to make figures and
//   presentations that are friendly to colorblind people", https://jfly.uni-koeln.de/color/

export const OKABE_ITO = {
  blue: "#0072b2",
  vermillion: "#d55e00",
  bluishGreen: "#009e73",
  orange: "#e69f00",
  reddishPurple: "#cc79a7",
  skyBlue: "#56b4e9",
} as const;

/** The force arrows in the 3D view. */
export const FORCE_COLORS = {
  normal: OKABE_ITO.blue,
  friction: OKABE_ITO.vermillion,
  weight: OKABE_ITO.bluishGreen,
} as const;

/** The plots' lines: a dashed line is also told apart by its dashes. */
export const PLOT_COLORS = {
  x: OKABE_ITO.blue,
  theory: "#595959",
  hall: OKABE_ITO.blue,
  pulse: OKABE_ITO.vermillion,
  accepted: OKABE_ITO.vermillion,
  rejected: "#767676",
} as const;
