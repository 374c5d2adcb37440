package minigolf.online.server;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.io.Content;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import minigolf.online.Json;
import minigolf.online.Protocol;
import minigolf.online.store.GameStore;
import minigolf.online.store.Score;

/**
 * The web pages on the server's port (docs/online.md, "Web page"): {@code /} lists the open rooms
 * with live scorecards (refreshed every few seconds by a small script; the page reads without it),
 * {@code /course/NAME} a course's or round's leaderboard; {@code /api/rooms} and
 * {@code /api/course/NAME} give the same as JSON. Every name a player typed is escaped. Private rooms
 * are not shown.
 */
final class WebPages extends Handler.Abstract {
    static final int LEADERBOARD_SIZE = 50;
    private static final DateTimeFormatter DAY = DateTimeFormatter.ofPattern("yyyy-MM-dd", Locale.ROOT).withZone(ZoneOffset.UTC);

    private final Rooms rooms;
    private final GameStore store;

    WebPages(Rooms rooms, GameStore store) {
        this.rooms = rooms;
        this.store = store;
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) {
        String path = Request.getPathInContext(request);
        if (!request.getMethod().equals("GET") && !request.getMethod().equals("HEAD")) {
            Response.writeError(request, response, callback, 405);
            return true;
        }
        if (path.equals("/")) {
            write(response, callback, "text/html", page("Minigolf: open rooms", "<main id=\"rooms\" data-refreshed=\"0\">"
                    + roomsHtml() + "</main>" + REFRESH_SCRIPT));
        } else if (path.equals("/rooms.html")) {
            write(response, callback, "text/html", roomsHtml());
        } else if (path.equals("/api/rooms")) {
            write(response, callback, "application/json", Json.write(roomsJson()));
        } else if (path.startsWith("/course/") || path.startsWith("/api/course/")) {
            boolean api = path.startsWith("/api/");
            String name = path.substring(path.indexOf("/course/") + "/course/".length());
            if (!Protocol.COURSE_NAME.matcher(name).matches()) {
                Response.writeError(request, response, callback, 404, "no such course");
                return true;
            }
            store.leaderboard(name, LEADERBOARD_SIZE).whenComplete((scores, err) -> {
                if (err != null) {
                    Response.writeError(request, response, callback, 500, "the database did not answer");
                } else if (api) {
                    write(response, callback, "application/json", Json.write(leaderboardJson(name, scores)));
                } else {
                    write(response, callback, "text/html", page("Leaderboard: " + name, leaderboardHtml(name, scores)));
                }
            });
        } else {
            Response.writeError(request, response, callback, 404, "no such page");
        }
        return true;
    }

    private static void write(Response response, Callback callback, String type, String body) {
        response.setStatus(200);
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, type + "; charset=utf-8");
        response.getHeaders().put(HttpHeader.CACHE_CONTROL, "no-store");
        response.getHeaders().put("X-Content-Type-Options", "nosniff");
        response.getHeaders().put("Content-Security-Policy", "default-src 'self'; script-src 'unsafe-inline' 'self';"
                + " style-src 'unsafe-inline'");
        Content.Sink.write(response, true, body, callback);
    }

    /** The rooms the page lists: listed ones, playing first, then waiting for players, then finished; newest first. */
    private List<RoomView> shown() {
        return rooms.all().stream().map(Room::view).filter(RoomView::listed)
                .sorted(Comparator.comparingInt((RoomView v) -> switch (v.status()) {
                    case "playing" -> 0;
                    case "lobby" -> 1;
                    default -> 2;
                }).thenComparing(Comparator.comparingLong(RoomView::updatedMs).reversed())).limit(200).toList();
    }

    String roomsHtml() {
        List<RoomView> views = shown();
        if (views.isEmpty()) return "<p class=\"empty\">No open rooms. Host one from the game: Play online, Host.</p>";
        StringBuilder sb = new StringBuilder();
        for (RoomView v : views) {
            sb.append("<section class=\"room\" data-code=\"").append(v.code()).append("\"><h2><a href=\"/course/")
                    .append(esc(v.course())).append("\">").append(esc(v.title())).append("</a> <span class=\"code\">")
                    .append(v.code()).append("</span></h2><p class=\"status\">").append(esc(statusLine(v)))
                    .append("</p><div class=\"scroll\"><table><thead><tr><th>Player</th>");
            for (int h = 0; h < v.pars().length; h++) sb.append("<th>").append(h + 1).append("</th>");
            sb.append("<th>Total</th></tr></thead><tbody>");
            if (v.isRound()) {
                sb.append("<tr class=\"par\"><td>Par</td>");
                int par = 0;
                for (int p : v.pars()) {
                    sb.append("<td>").append(p).append("</td>");
                    par += p;
                }
                sb.append("<td>").append(par).append("</td></tr>");
            }
            for (int s = 0; s < v.names().size(); s++) {
                String name = v.names().get(s);
                sb.append("<tr").append(s == v.turn() ? " class=\"turn\"" : "").append("><td>");
                if (name == null) {
                    sb.append("<em>free seat</em>");
                } else {
                    sb.append(esc(name));
                    if (v.levels().get(s) != null) sb.append(" <small>(bot)</small>");
                    else if (!v.connected().get(s)) sb.append(" <small>(away)</small>");
                }
                sb.append("</td>");
                for (int h = 0; h < v.pars().length; h++) {
                    int k = v.strokes()[s][h];
                    sb.append("<td>").append(k < 0 ? "" : String.valueOf(k)).append("</td>");
                }
                sb.append("<td class=\"total\">").append(v.total(s)).append("</td></tr>");
            }
            sb.append("</tbody></table></div></section>");
        }
        return sb.toString();
    }

    private static String statusLine(RoomView v) {
        return switch (v.status()) {
            case "lobby" -> {
                long free = v.names().stream().filter(n -> n == null).count();
                yield "waiting for " + free + " more player" + (free == 1 ? "" : "s") + ": join with the code";
            }
            case "playing" -> "hole " + (v.hole() + 1) + " of " + v.pars().length
                    + (v.turn() >= 0 ? ", " + v.names().get(v.turn()) + " to play" : "");
            default -> "finished";
        };
    }

    ObjectNode roomsJson() {
        ObjectNode o = Json.object();
        ArrayNode list = o.putArray("rooms");
        for (RoomView v : shown()) {
            ObjectNode r = list.addObject().put("room", v.code()).put("course", v.course()).put("title", v.title())
                    .put("kind", v.isRound() ? "round" : "course").put("status", v.status()).put("hole", v.hole())
                    .put("turn", v.turn());
            ArrayNode pars = r.putArray("pars");
            for (int p : v.pars()) pars.add(p);
            ArrayNode players = r.putArray("players");
            for (int s = 0; s < v.names().size(); s++) {
                ObjectNode p = players.addObject();
                if (v.names().get(s) == null) {
                    p.putNull("name");
                    continue;
                }
                p.put("name", v.names().get(s)).put("bot", v.levels().get(s) != null).put("connected", v.connected().get(s));
                ArrayNode strokes = p.putArray("strokes");
                for (int k : v.strokes()[s]) if (k >= 0) strokes.add(k);
                p.put("total", v.total(s));
            }
        }
        return o;
    }

    static String leaderboardHtml(String name, List<Score> scores) {
        StringBuilder sb = new StringBuilder("<main><h2>").append(esc(name)).append("</h2>");
        if (scores.isEmpty()) return sb.append("<p class=\"empty\">No finished scores yet.</p></main>").toString();
        sb.append("<div class=\"scroll\"><table><thead><tr><th>#</th><th>Player</th><th>Strokes</th><th>Par</th><th>Date</th>")
                .append("</tr></thead><tbody>");
        int rank = 0, shownRank = 0, last = Integer.MIN_VALUE;
        for (Score s : scores) {
            rank++;
            if (s.strokes() != last) shownRank = rank;
            last = s.strokes();
            sb.append("<tr><td>").append(shownRank).append("</td><td>").append(esc(s.name()));
            if (s.level() != null) sb.append(" <small>(bot: ").append(esc(s.level())).append(")</small>");
            sb.append("</td><td>").append(s.strokes()).append("</td><td>").append(s.par()).append("</td><td>")
                    .append(DAY.format(Instant.ofEpochMilli(s.finishedMs()))).append("</td></tr>");
        }
        return sb.append("</tbody></table></div><p><a href=\"/\">Open rooms</a></p></main>").toString();
    }

    static ObjectNode leaderboardJson(String name, List<Score> scores) {
        ObjectNode o = Json.object().put("course", name);
        ArrayNode list = o.putArray("scores");
        for (Score s : scores) {
            ObjectNode e = list.addObject().put("name", s.name()).put("strokes", s.strokes()).put("par", s.par())
                    .put("room", s.room()).put("finished", DAY.format(Instant.ofEpochMilli(s.finishedMs())));
            if (s.level() != null) e.put("bot", s.level());
        }
        return o;
    }

    private static String page(String title, String body) {
        return "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>" + esc(title) + "</title>"
                + "<style>" + STYLE + "</style></head><body><header><h1>" + esc(title) + "</h1></header>" + body + "</body></html>";
    }

    /** Phone first: one column, tables that scroll sideways with the names kept in view, large enough type. */
    private static final String STYLE = "body{font-family:system-ui,sans-serif;margin:0;padding:0 12px 24px;background:#f4f7f2;"
            + "color:#1c2a1c;font-size:17px;line-height:1.4}header h1{font-size:1.4em;margin:16px 0 8px}"
            + ".room{background:#fff;border-radius:10px;padding:10px 12px;margin:12px 0;box-shadow:0 1px 3px #0002}"
            + ".room h2{font-size:1.15em;margin:0 0 4px}.code{font-family:monospace;background:#e3efe0;padding:1px 6px;"
            + "border-radius:4px;font-size:.9em}.status{margin:0 0 8px;color:#456}.scroll{overflow-x:auto}"
            + "table{border-collapse:collapse;min-width:100%}th,td{padding:6px 8px;text-align:center;border-bottom:1px solid #dde}"
            + "th:first-child,td:first-child{text-align:left;position:sticky;left:0;background:#fff;white-space:nowrap}"
            + "tr.par td{color:#789}tr.turn td:first-child{font-weight:bold}td.total{font-weight:bold}"
            + "a{color:#1d6b2f}.empty{color:#567}";

    private static final String REFRESH_SCRIPT = "<script>(function(){var m=document.getElementById('rooms');"
            + "function refresh(){fetch('/rooms.html',{cache:'no-store'}).then(function(r){return r.ok?r.text():null})"
            + ".then(function(t){if(t!==null){m.innerHTML=t;m.dataset.refreshed=String(Number(m.dataset.refreshed)+1);}})"
            + ".catch(function(){});}refresh();setInterval(refresh,3000);})();</script>";

    static String esc(String s) {
        StringBuilder sb = new StringBuilder(s.length());
        for (char c : s.toCharArray()) {
            switch (c) {
                case '<' -> sb.append("&lt;");
                case '>' -> sb.append("&gt;");
                case '&' -> sb.append("&amp;");
                case '"' -> sb.append("&quot;");
                case '\'' -> sb.append("&#39;");
                default -> sb.append(c);
            }
        }
        return sb.toString();
    }
}
