// The Teach tab's views, in the order of their tabs. A view is a folder (its
// model.ts, draw.ts and controls.ts, see view.ts) and its entry here.
import { bakerView } from './baker/controls.ts';
import { bruteView } from './brute/controls.ts';
import { degreeView } from './degree/controls.ts';
import { gadgetView } from './gadget/controls.ts';
import { mixedView } from './mixed/controls.ts';
import { orderView } from './order/controls.ts';
import { satView } from './sat/controls.ts';
import { waterView } from './water/controls.ts';

export const TEACH_VIEWS = [satView, bakerView, gadgetView, degreeView, mixedView, bruteView, orderView, waterView] as const;
export type TeachTab = (typeof TEACH_VIEWS)[number]['id'];
