package minigolf.online.store;

import java.util.List;

/**
 * A room as the database keeps it: what was asked for, its seats, the round as it started (a saved
 * round's JSON, null while the room waits in its lobby) and every event since, in order.
 */
public record StoredRoom(String code, String course, boolean listed, int strokeLimit, int seats, String status,
                         long createdMs, String startSave, List<StoredSeat> seatList, List<String> events) {
    public StoredRoom {
        seatList = List.copyOf(seatList);
        events = List.copyOf(events);
    }
}
