package minigolf.bot.planner;

import minigolf.bot.Shot;

record Attempt(Shot shot, boolean holed, boolean converged, double miss, Eval last) {
    static Attempt failed(Shot shot) {
        return new Attempt(shot, false, false, Double.POSITIVE_INFINITY, null);
    }
}
