package minigolf.online.server;

import java.util.ArrayList;
import java.util.List;
import minigolf.game.PlayerState;
import minigolf.game.Round;
import minigolf.game.RoundGame;

/**
 * A room as the web page shows it: an immutable copy made on the room's thread after every change,
 * so the page reads it from any thread. {@code strokes[seat][hole]} holds the finished holes' scores
 * and, on the hole being played, the strokes so far (-1 where nothing was played yet).
 */
record RoomView(String code, String course, String title, boolean isRound, boolean listed, String status, int hole,
                int[] pars, List<String> names, List<String> levels, List<Boolean> connected, int[][] strokes,
                int turn, long updatedMs) {

    static RoomView of(Room room) {
        Seat[] seats = room.seats();
        Round r = room.entry.round();
        List<String> names = new ArrayList<>(), levels = new ArrayList<>();
        List<Boolean> connected = new ArrayList<>();
        for (Seat s : seats) {
            names.add(s.name);
            levels.add(s.level);
            connected.add(s.bot || s.client != null);
        }
        int[] pars = r.holes().stream().mapToInt(Round.Hole::par).toArray();
        int[][] strokes = new int[seats.length][pars.length];
        for (int[] row : strokes) java.util.Arrays.fill(row, -1);
        RoundGame rg = room.round();
        int hole = 0;
        if (rg != null) {
            int[][] card = rg.finishedScores();
            for (int h = 0; h < card.length; h++) for (int s = 0; s < seats.length; s++) strokes[s][h] = card[h][s];
            hole = rg.holeIndex();
            if (!rg.isOver()) {
                for (int s = 0; s < seats.length; s++) {
                    PlayerState p = rg.game().player(s);
                    if (p.total() > 0 || !p.isPlaying()) strokes[s][hole] = p.total();
                }
            }
        }
        return new RoomView(room.code, room.entry.name(), r.name(), room.entry.isRound(), room.listed,
                room.status().jsonName(), hole, pars, names, levels, connected, strokes, room.turn(), System.currentTimeMillis());
    }

    /** A seat's strokes so far over the holes played. */
    int total(int seat) {
        int t = 0;
        for (int v : strokes[seat]) if (v > 0) t += v;
        return t;
    }
}
