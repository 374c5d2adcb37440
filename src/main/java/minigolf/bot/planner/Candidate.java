package minigolf.bot.planner;

import minigolf.bot.Shot;

record Candidate(Shot shot, double distance) {
}
